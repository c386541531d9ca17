// Akinci et al.'s surface tension on the GPU (see SurfaceTensionKernels.cuh).
#include "cuda/CudaCheck.h"
#include "cuda/SurfaceTensionKernels.cuh"

namespace parafluid::sph::cuda
{
namespace
{
constexpr int kThreads = 128;

/// (dW/dr) / r at r^2 = rr, so that grad_i W_ij = this times (x_i - x_j) (SurfaceTension.cxx's).
__device__ float gradientFactor(const WendlandC2Kernel& w, float rr)
{
  return w.gradientFactor(sqrtf(rr));
}
__device__ float gradientFactor(const Poly6Kernel& w, float rr)
{
  return w.gradientFactorFromSquared(rr);
}

/// n_i = h sum_j (m / rho_j) grad_i W_ij, pointing into the fluid.
template<class Kernel>
__global__ void surfaceNormals(DeviceState a, float* normals, DeviceGrid g, AkinciConstants<Kernel> k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float q[3] = { a.x[i], a.y[i], a.z[i] };
  const float h2 = k.h * k.h;
  float n[3] = { 0.0f, 0.0f, 0.0f };
  g.forEachWithin(a.x, a.y, a.z, q, q, h2,
                  [&](std::uint32_t j, const float* d, float rr)
                  {
                    const float f = k.mass / __ldg(a.rho + j) * gradientFactor(k.w, rr);
                    for (int c = 0; c < 3; ++c)
                    {
                      n[c] += f * d[c];
                    }
                  });
  for (int d = 0; d < 3; ++d)
  {
    normals[static_cast<std::size_t>(d) * a.n + i] = k.h * n[d];
  }
}

/// The cohesion (and curvature) pair sums of SPHSolver::addSurfaceTension added to i's acceleration.
template<class Kernel>
__global__ void tension(DeviceState a, const float* normals, DeviceGrid g, AkinciConstants<Kernel> k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float q[3] = { a.x[i], a.y[i], a.z[i] };
  const float h2 = k.h * k.h, rhoI = a.rho[i], pullScale = k.gamma * k.mass;
  const float* nx = normals;
  const float* ny = normals + a.n;
  const float* nz = normals + 2 * static_cast<std::size_t>(a.n);
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

template<class Kernel>
void launchAkinciTension(const DeviceState& a, float* normals, const DeviceGrid& grid, const AkinciConstants<Kernel>& k,
                         cudaStream_t stream)
{
  if (a.n == 0)
    return;
  const unsigned int blocks = (a.n + kThreads - 1) / kThreads;
  if (k.curvature)
  {
    surfaceNormals<<<blocks, kThreads, 0, stream>>>(a, normals, grid, k);
  }
  tension<<<blocks, kThreads, 0, stream>>>(a, normals, grid, k);
  check(cudaGetLastError(), "the surface-tension kernels");
}

template void launchAkinciTension(const DeviceState&, float*, const DeviceGrid&,
                                  const AkinciConstants<WendlandC2Kernel>&, cudaStream_t);
template void launchAkinciTension(const DeviceState&, float*, const DeviceGrid&, const AkinciConstants<Poly6Kernel>&,
                                  cudaStream_t);
} // namespace parafluid::sph::cuda
