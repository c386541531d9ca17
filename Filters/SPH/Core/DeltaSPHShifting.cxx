// δ-SPH's particle shifting (Lind et al. 2012, with δ+-SPH's coefficient, Sun et al. 2017).
#include "parafluid/sph/DeltaSPHSolver.h"

#include "parafluid/common/SimdDispatch.h"
#include "private/DeltaSPHPairs.h"
#include "private/DeltaSPHShift.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"
#include "private/WallImages.h"

namespace parafluid::sph
{
using detail::forEachParticleByCell;
using detail::forEachWallImage;
using detail::threadCount;
using namespace delta;

namespace
{
/// What particle shifting sums over one query's neighbours.
struct ShiftingSums
{
  float kernelSum;   // sum_j W_ij
  float gradient[3]; // the concentration gradient sum_j (dW/dr)/r (1 + 0.2 (W_ij / W(dp))^4) (q - x_j)
};

/// The sums of particle shifting at q over the padded hits: sum_j W_ij into out[0] and the
/// concentration gradient sum_j (dW/dr)/r (1 + 0.2 (W_ij / W(dp))^4) (q - x_j) into out[1..3].
/// (The padding's far sentinel adds exactly zero: its kernel value and gradient vanish.)
__attribute__((always_inline)) inline void shiftingSumsBody(const float* px, const float* py, const float* pz,
                                                            const std::uint32_t* hits, std::uint32_t count,
                                                            const float* q, const WendlandC2Kernel& w,
                                                            float inverseWSpacing, ShiftingSums* out)
{
  float ws = 0.0f, gx = 0.0f, gy = 0.0f, gz = 0.0f;
#pragma omp simd reduction(+ : ws, gx, gy, gz)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const WendlandPair pair(w, __builtin_sqrtf(dx * dx + dy * dy + dz * dz));
    const float weight = shiftingWeight(pair, inverseWSpacing);
    ws += pair.value;
    gx += weight * dx;
    gy += weight * dy;
    gz += weight * dz;
  }
  out->kernelSum = ws;
  out->gradient[0] = gx;
  out->gradient[1] = gy;
  out->gradient[2] = gz;
}

PARAFLUID_SIMD_DISPATCH(shiftingSums,
                        (const float* px, const float* py, const float* pz, const std::uint32_t* hits,
                         std::uint32_t count, const float* q, const WendlandC2Kernel& w, float inverseWSpacing,
                         ShiftingSums* out),
                        (px, py, pz, hits, count, q, w, inverseWSpacing, out), shiftingSumsBody)
} // namespace

void DeltaSPHSolver::shiftParticles(SimulationParts& sim, float dt)
{
  // Particle shifting (Lind et al. 2012) with the coefficient of the δ+-SPH scheme (Sun, Colagrossi,
  // Marrone & Zhang 2017): each interior particle moves down the gradient of particle concentration,
  //   dr_i = -CFL Ma (2 h_s)^2 grad C_i, grad C_i = sum_j V_j (1 + 0.2 (W_ij / W(dp))^4) grad W_ij,
  // with h_s the smoothing length (half the support H), Ma = U_max / c0 and CFL = c0 dt / h_s, so
  // CFL Ma (2 h_s)^2 = 2 H U_max dt: the shift per unit time depends on neither c0 nor the step.
  // It keeps the distribution uniform where the flow stretches it (the vortices of a Taylor-Green
  // flow, a splash's rarefaction) without a force, also at the stagnation points where a vortex
  // lines particles up (where a coefficient proportional to |v_i| would vanish).
  // Free-surface particles (kernel sum below 0.9, their neighbourhood cut) are not shifted: their
  // concentration gradient points out of the fluid. Fluid at rest (U_max = 0) is not shifted.
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const std::size_t n = s.size();
  this->Shift.assign(3 * n, 0.0f);
  const WendlandC2Kernel w(p.smoothingLength);
  const float volume = p.particleMass / p.restDensity;
  const float inverseWSpacing = 1.0f / w.value(std::min(sim.particleSpacing(), 0.99f * p.smoothingLength));
  const float limit = 0.2f * sim.particleSpacing();
  const auto count = static_cast<std::int64_t>(n);
  const auto fastest = static_cast<float>(sim.largestLength(s.vx, s.vy, s.vz));
  if (fastest == 0.0f)
  {
    return;
  }
  const float diffusion = 2.0f * p.smoothingLength * fastest * dt * volume;
  forEachParticleByCell(sim.grid(), s, p.smoothingLength, threadCount(p), {},
                        [&](CandidateBuffer& c, std::uint32_t i)
                        {
                          const float position[3] = { s.x[i], s.y[i], s.z[i] };
                          float sum = 0.0f, g[3] = { 0.0f, 0.0f, 0.0f };
                          forEachWallImage(
                            position, position, p,
                            [&](const float* q, const float*, const float*, const float* scale, bool image)
                            {
                              // The pair loops' hits (an image's among its particle's own); no channel is read.
                              const PairInput in(c, q, w.h2, image);
                              ShiftingSums sums;
                              shiftingSums(in.px, in.py, in.pz, in.hits, in.count, q, w, inverseWSpacing, &sums);
                              sum += sums.kernelSum;
                              g[0] += scale[0] * sums.gradient[0];
                              g[1] += scale[1] * sums.gradient[1];
                              g[2] += scale[2] * sums.gradient[2];
                            });
                          particleShift(sum, g, volume, diffusion, limit, &this->Shift[3 * i]);
                        });
  // Applied after the pass (it reads every neighbour's position), through the walls' rules.
  const auto& b = p.domainBounds;
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < count; ++i)
  {
    float* position[3] = { &s.x[i], &s.y[i], &s.z[i] };
    for (int a = 0; a < 3; ++a)
    {
      *position[a] = shiftedCoordinate(*position[a], this->Shift[3 * i + a], b[2 * a], b[2 * a + 1], p.periodic[a],
                                       0.01f * sim.particleSpacing());
    }
  }
  sim.refreshGhosts({ s.x.data(), s.y.data(), s.z.data() });
}
} // namespace parafluid::sph
