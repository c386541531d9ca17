// Müller et al.'s WCSPH passes on the GPU (see MullerKernels.cuh).
#include "cuda/CudaCheck.h"
#include "cuda/MullerKernels.cuh"
#include "parafluid/sph/WallMirrors.h"

namespace parafluid::sph::cuda
{
namespace
{
constexpr int kThreads = 128;

unsigned int blocksFor(std::uint32_t n)
{
  return (n + kThreads - 1) / kThreads;
}

__device__ WallMirrors mirrorsAround(const float position[3], const DeviceWalls& w)
{
  return WallMirrors::around(position, w.bounds, w.support, w.noSlip, w.periodic);
}

__global__ void density(DeviceState a, DeviceGrid g, DeviceWalls w, MullerDensityConstants k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float position[3] = { a.x[i], a.y[i], a.z[i] };
  // The particle itself (r = 0) and, near walls, its images: the mirrored fluid fills the cut-off
  // neighbourhood, |x_i - R x_j| = |R x_i - x_j|.
  float sum = 0.0f;
  const auto add = [&](const float* q)
  {
    g.forEachWithin(a.x, a.y, a.z, position, q, k.h2,
                    [&](std::uint32_t, const float*, float rr)
                    {
                      const float e = k.h2 - rr;
                      sum += e * e * e;
                    });
  };
  add(position);
  const WallMirrors mirrors = mirrorsAround(position, w);
  for (int m = 0; m < mirrors.count; ++m)
  {
    float image[3];
    mirrors.image(m, position, image);
    add(image);
  }
  const float rho = k.densityScale * sum;
  a.rho[i] = rho;
  a.p[i] = detail::mullerPressure(rho, k.stiffness, k.rho0, k.clamp);
}

/// The pair sums of SPHForces.cxx's pairSums: pressure (+ viscosity) in force, viscosity in
/// viscous when summed apart, the colour field's unscaled gradient and Laplacian.
struct MullerSums
{
  float force[3] = { 0, 0, 0 };
  float viscous[3] = { 0, 0, 0 };
  float normal[3] = { 0, 0, 0 };
  float laplacian = 0.0f;
};

/// Adds the pairs of query q (velocity v, pressure pi; t as in SPHForces.cxx) with the particles
/// around `around` to s.
template<bool Viscosity, bool Tension, bool SeparateViscous>
__device__ void addPairs(const DeviceState& a, const DeviceGrid& g, const float around[3], const float q[3],
                         const float v[3], float pi, const detail::MullerConstants& k, const float t[3], MullerSums& s)
{
  g.forEachWithin(a.x, a.y, a.z, around, q, k.h2,
                  [&](std::uint32_t j, const float* d, float rr)
                  {
                    const float inverseRhoJ = 1.0f / __ldg(a.rho + j);
                    const float dist = sqrtf(rr);
                    const float w = k.h - dist;
                    const float pair = detail::mullerPressurePair(k, pi, __ldg(a.p + j), inverseRhoJ, w, dist);
                    for (int c = 0; c < 3; ++c)
                    {
                      s.force[c] += pair * d[c];
                    }
                    if (Viscosity)
                    {
                      const float vj[3] = { __ldg(a.vx + j), __ldg(a.vy + j), __ldg(a.vz + j) };
                      const float approach =
                        t[0] * (v[0] - vj[0]) * d[0] + t[1] * (v[1] - vj[1]) * d[1] + t[2] * (v[2] - vj[2]) * d[2];
                      const float laminar = detail::mullerLaminarPair(k, approach, rr, inverseRhoJ, w, dist);
                      const float viscous = detail::mullerViscousPair(k, inverseRhoJ, w);
                      for (int c = 0; c < 3; ++c)
                      {
                        s.force[c] += laminar * d[c];
                        (SeparateViscous ? s.viscous : s.force)[c] += viscous * (vj[c] - v[c]);
                      }
                    }
                    if (Tension)
                    {
                      const float e = k.h2 - rr;
                      const float gradient = inverseRhoJ * e * e;
                      for (int c = 0; c < 3; ++c)
                      {
                        s.normal[c] += gradient * d[c];
                      }
                      s.laplacian += inverseRhoJ * e * (3.0f * k.h2 - 7.0f * rr); // the particle itself counts (r = 0)
                    }
                  });
}

template<bool Viscosity, bool Tension>
__global__ void forces(DeviceState a, DeviceGrid g, DeviceWalls w, detail::MullerConstants k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float position[3] = { a.x[i], a.y[i], a.z[i] }, velocity[3] = { a.vx[i], a.vy[i], a.vz[i] };
  const float pi = a.p[i];
  const float ones[3] = { 1.0f, 1.0f, 1.0f };
  MullerSums sum;
  addPairs<Viscosity, Tension, false>(a, g, position, position, velocity, pi, k, ones, sum);
  // Mirror images map back as on the CPU (SPHForces.cxx): the query moves with S v_i, the
  // pressure and colour sums with R, the separate (no-slip) viscous sum with S.
  const WallMirrors mirrors = mirrorsAround(position, w);
  for (int m = 0; m < mirrors.count; ++m)
  {
    float image[3], imageVelocity[3], t[3];
    mirrors.image(m, position, image);
    for (int c = 0; c < 3; ++c)
    {
      imageVelocity[c] = mirrors.velocityScale[m][c] * velocity[c];
      t[c] = mirrors.velocityScale[m][c] * mirrors.scale[m][c];
    }
    MullerSums im;
    if (mirrors.noSlip(m))
    {
      addPairs<Viscosity, Tension, true>(a, g, position, image, imageVelocity, pi, k, t, im);
    }
    else
    {
      addPairs<Viscosity, Tension, false>(a, g, position, image, imageVelocity, pi, k, t, im);
    }
    for (int c = 0; c < 3; ++c)
    {
      sum.force[c] += mirrors.scale[m][c] * im.force[c];
      sum.viscous[c] += mirrors.velocityScale[m][c] * im.viscous[c];
      sum.normal[c] += mirrors.scale[m][c] * im.normal[c];
    }
    sum.laplacian += im.laplacian;
  }
  const float inv = 1.0f / a.rho[i];
  float acc[3];
  for (int c = 0; c < 3; ++c)
  {
    acc[c] = (sum.force[c] + sum.viscous[c]) * inv + w.gravity[c];
  }
  if (Tension)
  {
    detail::addColourFieldTension(k, sum.normal, sum.laplacian, inv, acc);
  }
  a.ax[i] = acc[0];
  a.ay[i] = acc[1];
  a.az[i] = acc[2];
}
} // namespace

void launchMullerDensity(const DeviceState& a, const DeviceGrid& grid, const DeviceWalls& walls,
                         const MullerDensityConstants& k, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  density<<<blocksFor(a.n), kThreads, 0, stream>>>(a, grid, walls, k);
  check(cudaGetLastError(), "the WCSPH density kernel");
}

void launchMullerForces(const DeviceState& a, const DeviceGrid& grid, const DeviceWalls& walls,
                        const detail::MullerConstants& k, bool viscosity, bool tension, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  const unsigned int blocks = blocksFor(a.n);
  if (viscosity)
  {
    if (tension)
      forces<true, true><<<blocks, kThreads, 0, stream>>>(a, grid, walls, k);
    else
      forces<true, false><<<blocks, kThreads, 0, stream>>>(a, grid, walls, k);
  }
  else
  {
    if (tension)
      forces<false, true><<<blocks, kThreads, 0, stream>>>(a, grid, walls, k);
    else
      forces<false, false><<<blocks, kThreads, 0, stream>>>(a, grid, walls, k);
  }
  check(cudaGetLastError(), "the WCSPH force kernel");
}
} // namespace parafluid::sph::cuda
