// Akinci et al.'s surface tension on the GPU (see SurfaceTensionKernels.cuh).
#include "cuda/CudaCheck.h"
#include "cuda/SurfaceTensionKernels.cuh"

namespace parafluid::sph::cuda
{
namespace
{
constexpr int kThreads = 128;

/// n_i = h sum_j (m / rho_j) grad_i W_ij, pointing into the fluid.
__global__ void surfaceNormals(DeltaArrays a, DeviceGrid g, AkinciConstants k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float q[3] = { a.x[i], a.y[i], a.z[i] };
  const float h2 = k.w.h2;
  float n[3] = { 0.0f, 0.0f, 0.0f };
  g.forEachWithin(a.x, a.y, a.z, q, q, h2,
                  [&](std::uint32_t j, const float* d, float rr)
                  {
                    const float f = k.mass / __ldg(a.rho + j) * k.w.gradientFactor(sqrtf(rr));
                    for (int c = 0; c < 3; ++c)
                    {
                      n[c] += f * d[c];
                    }
                  });
  for (int d = 0; d < 3; ++d)
  {
    a.push[static_cast<std::size_t>(d) * a.n + i] = k.w.h * n[d];
  }
}

/// The cohesion (and curvature) pair sums of SPHSolver::addSurfaceTension added to i's acceleration.
__global__ void tension(DeltaArrays a, DeviceGrid g, AkinciConstants k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float q[3] = { a.x[i], a.y[i], a.z[i] };
  const float h2 = k.w.h2, rhoI = a.rho[i], pullScale = k.gamma * k.mass;
  const float* nx = a.push;
  const float* ny = a.push + a.n;
  const float* nz = a.push + 2 * static_cast<std::size_t>(a.n);
  const float n[3] = { k.curvature ? nx[i] : 0.0f, k.curvature ? ny[i] : 0.0f, k.curvature ? nz[i] : 0.0f };
  float acc[3] = { 0.0f, 0.0f, 0.0f };
  g.forEachWithin(a.x, a.y, a.z, q, q, h2,
                  [&](std::uint32_t j, const float* d, float rr)
                  {
                    const float r = sqrtf(rr);
                    const float weight = 2.0f * k.rho0 / (rhoI + __ldg(a.rho + j));
                    const float pull = pullScale * k.cohesion(r) * (r > 0.0f ? 1.0f / r : 0.0f);
                    float curve[3] = { 0.0f, 0.0f, 0.0f };
                    if (k.curvature)
                    {
                      curve[0] = k.gamma * (n[0] - __ldg(nx + j));
                      curve[1] = k.gamma * (n[1] - __ldg(ny + j));
                      curve[2] = k.gamma * (n[2] - __ldg(nz + j));
                    }
                    for (int c = 0; c < 3; ++c)
                    {
                      acc[c] -= weight * (pull * d[c] + curve[c]);
                    }
                  });
  a.ax[i] += acc[0];
  a.ay[i] += acc[1];
  a.az[i] += acc[2];
}
} // namespace

void launchAkinciTension(const DeltaArrays& a, const DeviceGrid& grid, const AkinciConstants& k, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  const unsigned int blocks = (a.n + kThreads - 1) / kThreads;
  if (k.curvature)
  {
    surfaceNormals<<<blocks, kThreads, 0, stream>>>(a, grid, k);
  }
  tension<<<blocks, kThreads, 0, stream>>>(a, grid, k);
  check(cudaGetLastError(), "the surface-tension kernels");
}
} // namespace parafluid::sph::cuda
