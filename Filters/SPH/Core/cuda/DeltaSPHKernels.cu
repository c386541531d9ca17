// δ-SPH's passes on the GPU (see DeltaSPHKernels.cuh): the CPU passes' formulas, one thread a particle.
#include "cuda/CudaCheck.h"
#include "cuda/DeltaSPHKernels.cuh"
#include "parafluid/sph/WallMirrors.h"
#include "private/DeltaSPHFreeSurface.h"
#include "private/DeltaSPHMomentum.h"
#include "private/DeltaSPHOwnImage.h"
#include "private/DeltaSPHShift.h"
#include "private/GradientCorrection.h"
#include "private/WallImages.h"

namespace parafluid::sph::cuda
{
using namespace delta;

namespace
{
constexpr int kThreads = 128;
// The pair loops are held to 64 registers (8 blocks of 128 threads an SM): the occupancy that hides
// their loads' latency outweighs the few spilled values (30 % faster a step on the H200 than at the
// 105-111 registers the compiler picks alone).
constexpr int kPairBlocksPerSM = 8;

unsigned int blocksFor(std::uint32_t n)
{
  return (n + kThreads - 1) / kThreads;
}

void checkLaunch(const char* what)
{
  check(cudaGetLastError(), what);
}

/// Runs f(q, vq, scale, t, image) for particle i's queries: the particle itself, then its wall
/// images (forEachWallImage, no-slip walls included), whose mirrors are made only after the
/// particle's own sums, so that loop runs without them in registers.
template<class F>
__device__ void forEachQuery(const float position[3], const float velocity[3], const DeviceWalls& w, F&& f)
{
  const float ones[3] = { 1.0f, 1.0f, 1.0f };
  f(position, velocity, ones, ones, false);
  const WallMirrors mirrors = WallMirrors::around(position, w.bounds, w.support, w.noSlip, w.periodic);
  for (int m = 0; m < mirrors.count; ++m)
  {
    float q[3], vq[3], scale[3], t[3];
    mirrors.image(m, position, q);
    for (int d = 0; d < 3; ++d)
    {
      scale[d] = mirrors.scale[m][d];
      t[d] = mirrors.scale[m][d] * mirrors.velocityScale[m][d];
      vq[d] = scale[d] * velocity[d];
    }
    f(q, vq, scale, t, true);
  }
}

__global__ void __launch_bounds__(kThreads, kPairBlocksPerSM)
  continuity(DeltaArrays a, DeviceGrid g, DeviceWalls w, Constants k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float position[3] = { a.x[i], a.y[i], a.z[i] }, velocity[3] = { a.vx[i], a.vy[i], a.vz[i] };
  const float rhoI = a.rho[i], fullnessI = a.fullness[i], slowI = a.slow[i];
  float rate = 0.0f, moment[6] = { 0, 0, 0, 0, 0, 0 }, push[3] = { 0, 0, 0 }, least = 1.0f;
  forEachQuery(position, velocity, w,
               [&](const float* q, const float* vq, const float* scale, const float*, bool image)
               {
                 // Diffusion between real neighbours only (densityRateBody).
                 const float diffusion = image ? 0.0f : k.delta * k.hSmooth * k.c0 * 2.0f * k.mass;
                 float r = 0.0f, s[6] = { 0, 0, 0, 0, 0, 0 }, gx = 0.0f, gy = 0.0f, gz = 0.0f, l = 1.0f;
                 g.forEachNeighbour(
                   position,
                   [&](std::uint32_t j, const float* shift)
                   {
                     const float dx = q[0] - (__ldg(a.x + j) + shift[0]), dy = q[1] - (__ldg(a.y + j) + shift[1]),
                                 dz = q[2] - (__ldg(a.z + j) + shift[2]);
                     const float rr = dx * dx + dy * dy + dz * dz;
                     if (!(rr < k.h2))
                     {
                       return;
                     }
                     const WendlandPair wp(k.w, sqrtf(rr));
                     const float approach =
                       (vq[0] - __ldg(a.vx + j)) * dx + (vq[1] - __ldg(a.vy + j)) * dy + (vq[2] - __ldg(a.vz + j)) * dz;
                     const float hydrostatic =
                       -k.rho0 * (k.gravity[0] * dx + k.gravity[1] * dy + k.gravity[2] * dz) * k.inverseC0Squared;
                     const float rhoJ = __ldg(a.rho + j), fullnessJ = __ldg(a.fullness + j);
                     const float psi =
                       (rhoJ - rhoI) - hydrostatic - (1.0f - fullnessI * fullnessJ) * (__ldg(a.slow + j) - slowI);
                     r += wp.gradient * (k.mass * approach - diffusion * psi * (rr / (rhoJ * (rr + k.eta2))));
                     const float v = -k.mass * wp.gradient / rhoJ;
                     s[0] += v * dx * dx;
                     s[1] += v * dx * dy;
                     s[2] += v * dx * dz;
                     s[3] += v * dy * dy;
                     s[4] += v * dy * dz;
                     s[5] += v * dz * dz;
                     const float gj = k.mass * wp.gradient;
                     gx += gj * dx;
                     gy += gj * dy;
                     gz += gj * dz;
                     l = fullnessJ < l ? fullnessJ : l;
                   });
                 rate += r;
                 detail::addImageMoment(s, scale, moment);
                 push[0] += scale[0] * gx;
                 push[1] += scale[1] * gy;
                 push[2] += scale[2] * gz;
                 least = l < least ? l : least;
                 if (image)
                 {
                   rate += ownImageDensityRate(q, vq, position, velocity, k);
                 }
               });
  a.rate[i] = rate;
  if (a.correction)
  {
    detail::gradientCorrection(moment, k.pressureCorrection, a.correction + 6 * static_cast<std::size_t>(i));
  }
  const SurfaceMeasure surface = measureSurface(moment, least, k.pressureCorrection);
  a.nextFullness[i] = surface.fullness;
  a.interior[i] = surface.interior;
  for (int d = 0; d < 3; ++d)
  {
    a.push[static_cast<std::size_t>(d) * a.n + i] = surface.interior * push[d];
  }
}

__global__ void integrateDensity(DeltaArrays a, Constants k, float dt, float follow, float bulk)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  float rho = a.rho[i] + dt * a.rate[i];
  if (a.wall.distance)
  {
    // The mesh's wall moves density with the particle's position (DeltaSPHSolver::advanceDensity).
    const float sum = a.wall.table.at(a.wall.distance[i]).sum;
    rho += 2.0f * k.mass * (sum - a.wall.wallSum[i]);
    a.wall.wallSum[i] = sum;
  }
  a.rho[i] = rho;
  if (follow > 0.0f)
  {
    a.slow[i] += follow * (departureFromHydrostatic(k, a.x[i], a.y[i], a.z[i], rho) - a.slow[i]);
  }
  a.p[i] = taitPressure(rho, bulk, 1.0f / k.rho0);
}

template<bool Laminar>
__global__ void __launch_bounds__(kThreads, kPairBlocksPerSM)
  forces(DeltaArrays a, DeviceGrid g, DeviceWalls w, Constants k)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n)
  {
    return;
  }
  const float position[3] = { a.x[i], a.y[i], a.z[i] }, velocity[3] = { a.vx[i], a.vy[i], a.vz[i] };
  const float rhoI = a.rho[i], pI = a.p[i];
  const float inverseRhoI = 1.0f / rhoI;
  const float termI = pI * inverseRhoI * inverseRhoI;
  const float tensileI = pI < 0.0f ? -kTensileCoefficient * termI : 0.0f;
  const float massOverRhoI = k.mass * inverseRhoI;
  const float* pushX = a.push;
  const float* pushY = a.push + a.n;
  const float* pushZ = a.push + 2 * static_cast<std::size_t>(a.n);
  float acc[3] = { w.gravity[0], w.gravity[1], w.gravity[2] };
  float difference[3] = { 0, 0, 0 }, shepard = 0.0f, shepardPush[3] = { 0, 0, 0 };
  forEachQuery(position, velocity, w,
               [&](const float* q, const float* vq, const float* scale, const float* t, bool image)
               {
                 float lift[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
                 if (image && k.correctGradient)
                 {
                   detail::hydrostaticImageLift(q, position, scale, k.gravity, lift);
                 }
                 float sa[3] = { 0, 0, 0 }, sd[3] = { 0, 0, 0 }, sw = 0.0f, sp[3] = { 0, 0, 0 };
                 g.forEachNeighbour(
                   position,
                   [&](std::uint32_t j, const float* shift)
                   {
                     const float xj = __ldg(a.x + j) + shift[0], yj = __ldg(a.y + j) + shift[1],
                                 zj = __ldg(a.z + j) + shift[2];
                     const float dx = q[0] - xj, dy = q[1] - yj, dz = q[2] - zj;
                     const float rr = dx * dx + dy * dy + dz * dz;
                     if (!(rr < k.h2))
                     {
                       return;
                     }
                     const WendlandPair wp(k.w, sqrtf(rr));
                     const float rhoJ = __ldg(a.rho + j), pj = __ldg(a.p + j);
                     const float pJ = image ? pj + rhoJ * (lift[0] * xj + lift[1] * yj + lift[2] * zj + lift[3]) : pj;
                     const float vxj = __ldg(a.vx + j), vyj = __ldg(a.vy + j), vzj = __ldg(a.vz + j);
                     float laminar = 0.0f, inverseRhoJ;
                     const float scalar =
                       momentumFactor<Laminar>(dx, dy, dz, rr, wp.value, vq, vxj, vyj, vzj, rhoI, termI, tensileI, rhoJ,
                                               pJ, k, &laminar, &inverseRhoJ) *
                       (k.mass * wp.gradient);
                     sa[0] += scalar * dx;
                     sa[1] += scalar * dy;
                     sa[2] += scalar * dz;
                     const float diff = (pJ - pI) * (massOverRhoI * inverseRhoJ) * wp.gradient;
                     sd[0] += diff * dx;
                     sd[1] += diff * dy;
                     sd[2] += diff * dz;
                     const float smoothing = k.mass * inverseRhoJ * wp.value;
                     sw += smoothing;
                     sp[0] += smoothing * __ldg(pushX + j);
                     sp[1] += smoothing * __ldg(pushY + j);
                     sp[2] += smoothing * __ldg(pushZ + j);
                     if (Laminar)
                     {
                       float wx, wy, wz;
                       laminarVelocity<true>(vq, vxj, vyj, vzj, t, wx, wy, wz); // t is all ones for the particle itself
                       const float viscous = laminar * (k.mass * wp.gradient);
                       sa[0] += viscous * wx;
                       sa[1] += viscous * wy;
                       sa[2] += viscous * wz;
                     }
                   });
                 if (image)
                 {
                   addOwnImageForce<Laminar>(q, vq, t, position, velocity, rhoI, pI, k, sa);
                 }
                 for (int d = 0; d < 3; ++d)
                 {
                   acc[d] += scale[d] * sa[d];
                   difference[d] += scale[d] * sd[d];
                   shepardPush[d] += scale[d] * sp[d];
                 }
                 shepard += sw;
               });
  if (k.highPass && shepard > 0.0f)
  {
    // The push's high pass (SPHParameters::pushHighPass), as the CPU's force pass applies it.
    const float factor = 2.0f * k.pressureCorrection * pI / (rhoI * rhoI) * a.interior[i] / shepard;
    for (int d = 0; d < 3; ++d)
    {
      acc[d] += factor * shepardPush[d];
    }
  }
  if (a.correction)
  {
    detail::applyGradientCorrection(a.correction + 6 * static_cast<std::size_t>(i), difference, acc);
  }
  if (a.wall.distance && a.wall.distance[i] < a.wall.table.reach)
  {
    // The mesh's lattice is the particle's mirror image, p_b = p_i (DeltaSPHForces.cxx).
    const float scalar = -2.0f * k.pressureCorrection * termI * k.mass * a.wall.table.at(a.wall.distance[i]).slope;
    for (int d = 0; d < 3; ++d)
    {
      acc[d] += scalar * a.wall.normal[static_cast<std::size_t>(d) * a.n + i];
    }
  }
  a.ax[i] = acc[0];
  a.ay[i] = acc[1];
  a.az[i] = acc[2];
}

__global__ void __launch_bounds__(kThreads, kPairBlocksPerSM)
  shiftSums(DeltaArrays a, DeviceGrid g, DeviceWalls w, Constants k, ShiftConstants c, const StepMeasures* measured)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  const float fastest = sqrtf(measured->fastestSquared);
  if (i >= a.n || fastest == 0.0f)
  {
    return;
  }
  const float position[3] = { a.x[i], a.y[i], a.z[i] };
  float sum = 0.0f, gradient[3] = { 0, 0, 0 };
  forEachQuery(position, position, w,
               [&](const float* q, const float*, const float* scale, const float*, bool)
               {
                 float ws = 0.0f, gx = 0.0f, gy = 0.0f, gz = 0.0f;
                 g.forEachWithin(a.x, a.y, a.z, position, q, k.h2,
                                 [&](std::uint32_t, const float* d, float rr)
                                 {
                                   const WendlandPair pair(k.w, sqrtf(rr));
                                   const float weight = shiftingWeight(pair, c.inverseWSpacing);
                                   ws += pair.value;
                                   gx += weight * d[0];
                                   gy += weight * d[1];
                                   gz += weight * d[2];
                                 });
                 sum += ws;
                 gradient[0] += scale[0] * gx;
                 gradient[1] += scale[1] * gy;
                 gradient[2] += scale[2] * gz;
               });
  float shift[3];
  particleShift(sum, gradient, c.volume, c.twiceSupportDt * fastest * c.volume, c.limit, shift);
  for (int d = 0; d < 3; ++d)
  {
    a.push[static_cast<std::size_t>(d) * a.n + i] = shift[d];
  }
}

__global__ void applyShift(DeltaArrays a, DeviceWalls w, ShiftConstants c, const StepMeasures* measured)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= a.n || measured->fastestSquared == 0.0f)
  {
    return;
  }
  float* position[3] = { a.x, a.y, a.z };
  for (int d = 0; d < 3; ++d)
  {
    position[d][i] = shiftedCoordinate(position[d][i], a.push[static_cast<std::size_t>(d) * a.n + i], w.bounds[2 * d],
                                       w.bounds[2 * d + 1], w.periodic[d], c.margin);
  }
}

} // namespace

void launchContinuity(const DeltaArrays& a, const DeviceGrid& grid, const DeviceWalls& walls, const Constants& k,
                      cudaStream_t stream)
{
  if (a.n == 0)
    return;
  continuity<<<blocksFor(a.n), kThreads, 0, stream>>>(a, grid, walls, k);
  checkLaunch("the continuity kernel");
}

void launchIntegrateDensity(const DeltaArrays& a, const Constants& k, float dt, float follow, float bulk,
                            cudaStream_t stream)
{
  if (a.n == 0)
    return;
  integrateDensity<<<blocksFor(a.n), kThreads, 0, stream>>>(a, k, dt, follow, bulk);
  checkLaunch("the density kernel");
}

void launchForces(const DeltaArrays& a, const DeviceGrid& grid, const DeviceWalls& walls, const Constants& k,
                  bool laminar, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  if (laminar)
    forces<true><<<blocksFor(a.n), kThreads, 0, stream>>>(a, grid, walls, k);
  else
    forces<false><<<blocksFor(a.n), kThreads, 0, stream>>>(a, grid, walls, k);
  checkLaunch("the force kernel");
}

void launchShift(const DeltaArrays& a, const DeviceGrid& grid, const DeviceWalls& walls, const Constants& k,
                 const ShiftConstants& shift, const StepMeasures* measured, cudaStream_t stream)
{
  if (a.n == 0)
    return;
  shiftSums<<<blocksFor(a.n), kThreads, 0, stream>>>(a, grid, walls, k, shift, measured);
  applyShift<<<blocksFor(a.n), kThreads, 0, stream>>>(a, walls, shift, measured);
  checkLaunch("the shifting kernels");
}

} // namespace parafluid::sph::cuda
