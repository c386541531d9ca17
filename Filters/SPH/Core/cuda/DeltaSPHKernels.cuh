#pragma once
// Internal to the CUDA backend: δ-SPH's passes on the GPU, one thread per particle over the state
// sorted by cell, each the CPU pass's formulas (private/DeltaSPH*.h) in a plain loop over the
// neighbouring cells. Every sum runs in a fixed order, so a rerun gives the same bits.
#include "cuda/DeviceGrid.cuh"
#include "cuda/DeviceMesh.cuh"
#include "private/DeltaSPHPairs.h"
#include "private/LogLawFriction.h"

#include <cuda_runtime.h>

#include <array>
#include <cstdint>

namespace parafluid::sph::cuda
{
/// The state and δ-SPH's own arrays on the GPU, one value per particle unless said.
struct DeltaArrays
{
  std::uint32_t n = 0;
  float *x, *y, *z, *vx, *vy, *vz, *ax, *ay, *az;
  float* rho;          // integrated density [kg/m^3]
  float* p;            // pressure [Pa]
  float* rate;         // D rho / D t of the last continuity pass
  float* fullness;     // DeltaSPHSolver::Fullness, a step old
  float* nextFullness; // the continuity pass's, swapped in after it
  float* slow;         // DeltaSPHSolver::SlowDeparture
  float* correction;   // 6 per particle (gradient correction), or null
  float* push;         // 3 n: x, y and z of DeltaSPHSolver::FullPush
  float* interior;     // DeltaSPHSolver::Interior
  float* impulse;      // sum of p dt over an advance [Pa s]
  MeshContacts wall;   // the boundary mesh's wall in the sums (distance null: none)
};

/// The box and what its walls do (SPHParameters).
struct DeviceWalls
{
  std::array<float, 6> bounds;
  float support; // h [m]
  std::array<bool, 6> noSlip;
  std::array<bool, 3> periodic;
  float restitution;
  float damping;    // SPHParameters::boundaryDamping, at the mesh
  float gravity[3]; // [m/s^2], as given (Constants::gravity drops it along periodic axes)
};

/// What the time-step control and the blow-up checks read after a step; sums in double.
struct StepMeasures
{
  double compression;     // sum of max(rho - rho0, 0)
  double speedSquaredSum; // sum of |v|^2
  float fastestSquared, largestAccelerationSquared, densest;
  unsigned int nonFinite; // particles with a non-finite position or velocity
  float lo[3], hi[3];     // the particles' bounding box [m]
};

void launchKick(const DeltaArrays& a, float dt, cudaStream_t stream);
/// The moves of a step (detail::driftParticle): through the box and past `mesh` (triangleCount 0: none).
void launchDrift(const DeltaArrays& a, const DeviceWalls& walls, const TriangleMeshView& mesh, float dt,
                 cudaStream_t stream);
/// D rho / D t into rate, the gradient correction, nextFullness, interior and push (DeltaSPHContinuity.cxx).
void launchContinuity(const DeltaArrays& a, const DeviceGrid& grid, const DeviceWalls& walls, const delta::Constants& k,
                      cudaStream_t stream);
/// rho += dt rate and the mesh wall's change since the last step, the slow departure follows by
/// `follow` (0: not at all), p from Tait's equation (DeltaSPHSolver::advanceDensity, updatePressure).
void launchIntegrateDensity(const DeltaArrays& a, const delta::Constants& k, float dt, float follow, float bulk,
                            cudaStream_t stream);
/// The accelerations (DeltaSPHForces.cxx); laminar: the fluid's viscosity is on.
void launchForces(const DeltaArrays& a, const DeviceGrid& grid, const DeviceWalls& walls, const delta::Constants& k,
                  bool laminar, cudaStream_t stream);
/// The law of the wall's braking near the box walls (detail::brakeAtWalls).
void launchWallFriction(const DeltaArrays& a, const detail::LogLawWalls& walls, float dt, cudaStream_t stream);
/// Particle shifting's constants (DeltaSPHSolver::shiftParticles): 1 / W(spacing), a particle's
/// volume m / rho0 [m^3], the longest shift (0.2 spacings) and the walls' margin (0.01) [m], and
/// 2 H dt [m s], which times the fastest speed and the volume gives the diffusion coefficient.
struct ShiftConstants
{
  float inverseWSpacing, volume, limit, margin, twiceSupportDt;
};
/// Shifts each interior particle down its concentration gradient through the box's rules, with the
/// fastest speed read from measured->fastestSquared (device memory; no shift when it is 0). a.push
/// (3 n) holds the shifts meanwhile: the continuity pass that follows writes it anew.
void launchShift(const DeltaArrays& a, const DeviceGrid& grid, const DeviceWalls& walls, const delta::Constants& k,
                 const ShiftConstants& shift, const StepMeasures* measured, cudaStream_t stream);
/// The measures into *result (device memory), `partials` room for kMeasureBlocks; impulse += weight p
/// when weight > 0.
constexpr int kMeasureBlocks = 1024;
void launchMeasure(const DeltaArrays& a, float rho0, float weight, StepMeasures* partials, StepMeasures* result,
                   cudaStream_t stream);
/// p = scale impulse: each particle's time-weighted mean pressure over an advance.
void launchMeanPressure(const DeltaArrays& a, float scale, cudaStream_t stream);
/// dst[k] = src[order[k]] for k < n (float, std::int64_t and std::uint32_t).
template<class T>
void launchGather(const T* src, T* dst, const std::uint32_t* order, std::uint32_t n, cudaStream_t stream);
} // namespace parafluid::sph::cuda
