// The passes over the state that every solver shares, on the GPU (see StateKernels.cuh).
#include "cuda/CudaCheck.h"
#include "cuda/StateKernels.cuh"
#include "private/ParticleDrift.h"

#include <algorithm>

namespace parafluid::sph::cuda
{
namespace
{
constexpr int kThreads = 128;

unsigned int blocksFor(std::uint32_t n)
{
  return (n + kThreads - 1) / kThreads;
}

void checkLaunch(const char* what)
{
  check(cudaGetLastError(), what);
}

__global__ void kick(DeviceState a, float dt)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  a.vx[i] += dt * a.ax[i];
  a.vy[i] += dt * a.ay[i];
  a.vz[i] += dt * a.az[i];
}

__global__ void drift(DeviceState a, DeviceWalls w, TriangleMeshView mesh, float dt)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  detail::DriftWalls walls;
  for (int d = 0; d < 6; ++d)
  {
    walls.bounds[d] = w.bounds[d];
  }
  for (int d = 0; d < 3; ++d)
  {
    walls.periodic[d] = w.periodic[d];
  }
  walls.restitution = w.restitution;
  walls.mesh = mesh.triangleCount > 0 ? &mesh : nullptr;
  walls.damping = w.damping;
  walls.offset = 1e-3f * w.support; // SPHSolver::drift's
  float position[3] = { a.x[i], a.y[i], a.z[i] }, velocity[3] = { a.vx[i], a.vy[i], a.vz[i] };
  detail::driftParticle(position, velocity, dt, walls);
  a.x[i] = position[0];
  a.y[i] = position[1];
  a.z[i] = position[2];
  a.vx[i] = velocity[0];
  a.vy[i] = velocity[1];
  a.vz[i] = velocity[2];
}

__global__ void wallFriction(DeviceState a, detail::LogLawWalls w, float dt)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float position[3] = { a.x[i], a.y[i], a.z[i] };
  float velocity[3] = { a.vx[i], a.vy[i], a.vz[i] };
  detail::brakeAtWalls(position, velocity, dt, w);
  a.vx[i] = velocity[0];
  a.vy[i] = velocity[1];
  a.vz[i] = velocity[2];
}

__device__ void combine(StepMeasures& into, const StepMeasures& m)
{
  into.compression += m.compression;
  into.speedSquaredSum += m.speedSquaredSum;
  into.fastestSquared = fmaxf(into.fastestSquared, m.fastestSquared);
  into.largestAccelerationSquared = fmaxf(into.largestAccelerationSquared, m.largestAccelerationSquared);
  into.densest = fmaxf(into.densest, m.densest);
  into.nonFinite += m.nonFinite;
  for (int d = 0; d < 3; ++d)
  {
    into.lo[d] = fminf(into.lo[d], m.lo[d]);
    into.hi[d] = fmaxf(into.hi[d], m.hi[d]);
  }
}

__device__ StepMeasures emptyMeasures()
{
  StepMeasures m;
  m.compression = m.speedSquaredSum = 0.0;
  m.fastestSquared = m.largestAccelerationSquared = m.densest = 0.0f;
  m.nonFinite = 0;
  for (int d = 0; d < 3; ++d)
  {
    m.lo[d] = 3.0e38f;
    m.hi[d] = -3.0e38f;
  }
  return m;
}

constexpr int kMeasureThreads = 256;

/// The block's measures combined in a fixed tree (so the sums' order never changes) into out.
__device__ void reduceBlock(StepMeasures mine, StepMeasures* out)
{
  __shared__ StepMeasures shared[kMeasureThreads];
  shared[threadIdx.x] = mine;
  __syncthreads();
  for (int half = kMeasureThreads / 2; half > 0; half /= 2)
  {
    if (static_cast<int>(threadIdx.x) < half)
    {
      combine(shared[threadIdx.x], shared[threadIdx.x + half]);
    }
    __syncthreads();
  }
  if (threadIdx.x == 0)
  {
    *out = shared[0];
  }
}

__global__ void measure(DeviceState a, float rho0, float weight, StepMeasures* partials)
{
  StepMeasures m = emptyMeasures();
  for (std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < a.n; i += gridDim.x * blockDim.x)
  {
    const float v2 = a.vx[i] * a.vx[i] + a.vy[i] * a.vy[i] + a.vz[i] * a.vz[i];
    const float a2 = a.ax[i] * a.ax[i] + a.ay[i] * a.ay[i] + a.az[i] * a.az[i];
    const float position[3] = { a.x[i], a.y[i], a.z[i] };
    const bool finite = isfinite(v2) && isfinite(position[0] + position[1] + position[2]);
    m.nonFinite += finite ? 0u : 1u;
    m.speedSquaredSum += static_cast<double>(a.vx[i]) * a.vx[i] + static_cast<double>(a.vy[i]) * a.vy[i] +
                         static_cast<double>(a.vz[i]) * a.vz[i];
    m.fastestSquared = fmaxf(m.fastestSquared, v2);
    m.largestAccelerationSquared = fmaxf(m.largestAccelerationSquared, a2);
    const float rho = a.rho[i];
    m.compression += rho > rho0 ? rho - rho0 : 0.0f;
    m.densest = fmaxf(m.densest, rho);
    for (int d = 0; d < 3; ++d)
    {
      m.lo[d] = fminf(m.lo[d], position[d]);
      m.hi[d] = fmaxf(m.hi[d], position[d]);
    }
    if (weight > 0.0f)
    {
      a.impulse[i] += weight * a.p[i];
    }
  }
  reduceBlock(m, partials + blockIdx.x);
}

__global__ void measureTotal(const StepMeasures* partials, int count, StepMeasures* result)
{
  StepMeasures m = emptyMeasures();
  for (int b = threadIdx.x; b < count; b += blockDim.x)
  {
    combine(m, partials[b]);
  }
  reduceBlock(m, result);
}

__global__ void meanPressure(DeviceState a, float scale)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < a.n)
  {
    a.p[i] = scale * a.impulse[i];
  }
}

template<class T>
__global__ void gather(const T* src, T* dst, const std::uint32_t* order, std::uint32_t n)
{
  const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k < n)
  {
    dst[k] = src[order[k]];
  }
}
} // namespace

void launchKick(const DeviceState& a, float dt, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  kick<<<blocksFor(a.n), kThreads, 0, stream>>>(a, dt);
  checkLaunch("the kick kernel");
}

void launchDrift(const DeviceState& a, const DeviceWalls& walls, const TriangleMeshView& mesh, float dt,
                 cudaStream_t stream)
{
  if (a.n == 0)
    return;
  drift<<<blocksFor(a.n), kThreads, 0, stream>>>(a, walls, mesh, dt);
  checkLaunch("the drift kernel");
}

void launchWallFriction(const DeviceState& a, const detail::LogLawWalls& walls, float dt, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  wallFriction<<<blocksFor(a.n), kThreads, 0, stream>>>(a, walls, dt);
  checkLaunch("the wall-friction kernel");
}

void launchMeasure(const DeviceState& a, float rho0, float weight, StepMeasures* partials, StepMeasures* result,
                   cudaStream_t stream)
{
  const unsigned int blocks =
    std::max(1u, std::min<unsigned int>(kMeasureBlocks, (a.n + kMeasureThreads - 1) / kMeasureThreads));
  measure<<<blocks, kMeasureThreads, 0, stream>>>(a, rho0, weight, partials);
  measureTotal<<<1, kMeasureThreads, 0, stream>>>(partials, static_cast<int>(blocks), result);
  checkLaunch("the measure kernels");
}

void launchMeanPressure(const DeviceState& a, float scale, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  meanPressure<<<blocksFor(a.n), kThreads, 0, stream>>>(a, scale);
  checkLaunch("the mean-pressure kernel");
}

template<class T>
void launchGather(const T* src, T* dst, const std::uint32_t* order, std::uint32_t n, cudaStream_t stream)
{
  if (n == 0)
    return;
  gather<<<blocksFor(n), kThreads, 0, stream>>>(src, dst, order, n);
  checkLaunch("the gather kernel");
}

template void launchGather(const float*, float*, const std::uint32_t*, std::uint32_t, cudaStream_t);
template void launchGather(const std::int64_t*, std::int64_t*, const std::uint32_t*, std::uint32_t, cudaStream_t);
template void launchGather(const std::uint32_t*, std::uint32_t*, const std::uint32_t*, std::uint32_t, cudaStream_t);
} // namespace parafluid::sph::cuda
