#pragma once
// Internal to the CUDA backend: the passes over the state that every solver's step shares (the
// leapfrog's kick and drift, the law of the wall, the measures, the sort's gather), one thread a
// particle.
#include "cuda/DeviceState.cuh"
#include "private/LogLawFriction.h"

#include <cuda_runtime.h>

namespace parafluid::sph::cuda
{
/// v += dt a.
void launchKick(const DeviceState& a, float dt, cudaStream_t stream);
/// The moves of a step (detail::driftParticle): through the box and past `mesh` (triangleCount 0: none).
void launchDrift(const DeviceState& a, const DeviceWalls& walls, const TriangleMeshView& mesh, float dt,
                 cudaStream_t stream);
/// The law of the wall's braking near the box walls (detail::brakeAtWalls).
void launchWallFriction(const DeviceState& a, const detail::LogLawWalls& walls, float dt, cudaStream_t stream);
/// The measures into *result (device memory), `partials` room for kMeasureBlocks; impulse += weight p
/// when weight > 0.
constexpr int kMeasureBlocks = 1024;
void launchMeasure(const DeviceState& a, float rho0, float weight, StepMeasures* partials, StepMeasures* result,
                   cudaStream_t stream);
/// p = scale impulse: each particle's time-weighted mean pressure over an advance.
void launchMeanPressure(const DeviceState& a, float scale, cudaStream_t stream);
/// dst[k] = src[order[k]] for k < n (float, std::int64_t and std::uint32_t).
template<class T>
void launchGather(const T* src, T* dst, const std::uint32_t* order, std::uint32_t n, cudaStream_t stream);
} // namespace parafluid::sph::cuda
