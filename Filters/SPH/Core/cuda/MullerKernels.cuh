#pragma once
// Internal to the CUDA backend: Müller et al.'s (2003) WCSPH passes on the GPU, one thread per
// particle over the state sorted by cell: the CPU's formulas (WCSPHSolver.cxx, SPHForces.cxx,
// private/MullerPairs.h) with each particle's wall images, every sum in a fixed order.
#include "cuda/DeviceGrid.cuh"
#include "cuda/DeviceState.cuh"
#include "private/MullerPairs.h"

#include <cuda_runtime.h>

namespace parafluid::sph::cuda
{
/// The equation of state's constants: m times poly6's constant, GasStiffness [Pa m^3/kg],
/// RestDensity [kg/m^3] and ClampNegativePressure.
struct MullerDensityConstants
{
  float h2, densityScale, stiffness, rho0;
  bool clamp;
};

/// rho from the poly6 sum over the neighbours and the wall images, then p = k (rho - rho0)
/// (WCSPHSolver::computeDensityAndPressure).
void launchMullerDensity(const DeviceState& a, const DeviceGrid& grid, const DeviceWalls& walls,
                         const MullerDensityConstants& k, cudaStream_t stream);
/// The accelerations of Müller's forces with gravity (SPHSolver::computeAccelerations with the
/// pressure): viscosity (Müller's and the laminar term) and colour-field tension when on.
void launchMullerForces(const DeviceState& a, const DeviceGrid& grid, const DeviceWalls& walls,
                        const detail::MullerConstants& k, bool viscosity, bool tension, cudaStream_t stream);
} // namespace parafluid::sph::cuda
