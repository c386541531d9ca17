#pragma once
// Internal to the CUDA backend: δ-SPH's passes on the GPU, one thread per particle over the state
// sorted by cell, each the CPU pass's formulas (private/DeltaSPH*.h) in a plain loop over the
// neighbouring cells. Every sum runs in a fixed order, so a rerun gives the same bits.
#include "cuda/DeviceGrid.cuh"
#include "cuda/StateKernels.cuh"
#include "private/DeltaSPHPairs.h"

#include <cuda_runtime.h>

#include <cstdint>

namespace parafluid::sph::cuda
{
/// The state and δ-SPH's own arrays on the GPU, one value per particle unless said.
struct DeltaArrays : DeviceState
{
  float* rate;         // D rho / D t of the last continuity pass
  float* fullness;     // DeltaSPHSolver::Fullness, a step old
  float* nextFullness; // the continuity pass's, swapped in after it
  float* slow;         // DeltaSPHSolver::SlowDeparture
  float* correction;   // 6 per particle (gradient correction), or null
  float* push;         // 3 n: x, y and z of DeltaSPHSolver::FullPush
  float* interior;     // DeltaSPHSolver::Interior
};

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
} // namespace parafluid::sph::cuda
