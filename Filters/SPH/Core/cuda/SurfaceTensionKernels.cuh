#pragma once
// Internal to the CUDA backend: Akinci et al.'s (2013) surface tension on the GPU, the CPU's
// SPHSolver::addSurfaceTension (SurfaceTension.cxx) one thread a particle, between real particles.
#include "cuda/DeltaSPHKernels.cuh"
#include "private/AkinciTension.h"

namespace parafluid::sph::cuda
{
struct AkinciConstants
{
  detail::CohesionKernel cohesion;
  WendlandC2Kernel w; // the density kernel, for the surface normals
  float mass, rho0, gamma;
  bool curvature; // SurfaceTensionModel::Akinci (else the cohesion alone)
};

/// a.ax, a.ay, a.az += the surface tension; with the curvature term the surface normals are
/// summed first into a.push (3 n), which the force pass has read by then.
void launchAkinciTension(const DeltaArrays& a, const DeviceGrid& grid, const AkinciConstants& k, cudaStream_t stream);
} // namespace parafluid::sph::cuda
