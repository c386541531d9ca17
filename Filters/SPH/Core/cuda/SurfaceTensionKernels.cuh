#pragma once
// Internal to the CUDA backend: Akinci et al.'s (2013) surface tension on the GPU, the CPU's
// SPHSolver::addSurfaceTension (SurfaceTension.cxx) one thread a particle, between real particles.
#include "cuda/DeviceGrid.cuh"
#include "cuda/DeviceState.cuh"
#include "parafluid/common/Kernels.h"
#include "private/AkinciTension.h"

namespace parafluid::sph::cuda
{
/// Kernel: the solver's density kernel (WendlandC2Kernel or Poly6Kernel), for the surface normals.
template<class Kernel>
struct AkinciConstants
{
  detail::CohesionKernel cohesion;
  Kernel w;
  float h;
  float mass, rho0, gamma;
  bool curvature; // SurfaceTensionModel::Akinci (else the cohesion alone)
};

/// a.ax, a.ay, a.az += the surface tension; with the curvature term the surface normals are
/// summed first into `normals` (3 n, free for the pass's use).
template<class Kernel>
void launchAkinciTension(const DeviceState& a, float* normals, const DeviceGrid& grid, const AkinciConstants<Kernel>& k,
                         cudaStream_t stream);
} // namespace parafluid::sph::cuda
