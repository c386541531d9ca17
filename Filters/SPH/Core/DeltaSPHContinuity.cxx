// δ-SPH's density: Tait's equation of state, and the continuity equation with density diffusion,
// whose pass also sums the first moments of the gradient correction and the free-surface measures.
#include "parafluid/sph/DeltaSPHSolver.h"

#include "parafluid/common/SimdDispatch.h"
#include "private/DeltaSPHFreeSurface.h"
#include "private/DeltaSPHOwnImage.h"
#include "private/DeltaSPHPairs.h"
#include "private/GradientCorrection.h"
#include "private/MeshWall.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"
#include "private/WallImages.h"

namespace parafluid::sph
{
using detail::addImageMoment;
using detail::forEachParticleByCell;
using detail::forEachWallImage;
using detail::gradientCorrection;
using detail::threadCount;
using namespace delta;

namespace
{
/// What the continuity pass sums over one query's neighbours.
struct ContinuitySums
{
  float densityRate;   // D rho_i / D t [kg/m^3/s]
  float moment[6];     // the first moment sum_j V_j (x_j - x_i) (x) grad W_ij: xx, xy, xz, yy, yz, zz
  float push[3];       // G = sum_j m grad W_ij, the 2 p_i term's sum (pushHighPass)
  float leastFullness; // the smallest fullness (a step old) among the neighbours
};

/// D rho_i / D t: continuity, plus (when `diffuse`: real neighbours only, an image's density is the
/// particle's own, not that of the depth it is mirrored to) diffusion of the density's departure
/// from hydrostatic (Fourtakas et al. 2019, linearised: rho_j^H - rho_i^H = rho0 g . (x_j - x_i) /
/// c0^2 to first order in the compression, which stays about 1 % at c0 = 10 v_max). Between
/// particles whose neighbourhoods are full (fullness 1) the whole departure diffuses; as either
/// nears a free surface, only its fast part, the departure less its slow part (see
/// DeltaSPHSolver::SlowDeparture).
__attribute__((always_inline)) inline void densityRateBody(const PairInput& in, const float* q, const float* vq,
                                                           float rhoI, bool diffuse, float fullnessI, float slowI,
                                                           const Constants& k, ContinuitySums* out)
{
  const std::uint32_t count = in.count;
  const float *px = in.px, *py = in.py, *pz = in.pz;
  const float *vx = in.vx, *vy = in.vy, *vz = in.vz;
  const float* rho = in.rho;
  const float *fullness = in.fullness, *slow = in.slowDeparture;
  const std::uint32_t* hits = in.hits;
  const float diffusion = diffuse ? k.delta * k.hSmooth * k.c0 * 2.0f * k.mass : 0.0f;
  float rate = 0.0f, mxx = 0.0f, mxy = 0.0f, mxz = 0.0f, myy = 0.0f, myz = 0.0f, mzz = 0.0f;
  float gx = 0.0f, gy = 0.0f, gz = 0.0f, least = 1.0f;
#pragma omp simd reduction(+ : rate, mxx, mxy, mxz, myy, myz, mzz, gx, gy, gz) reduction(min : least)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const float rr = dx * dx + dy * dy + dz * dz;
    const WendlandPair w(k.w, __builtin_sqrtf(rr));
    const float approach = (vq[0] - vx[j]) * dx + (vq[1] - vy[j]) * dy + (vq[2] - vz[j]) * dz;
    const float hydrostatic =
      -k.rho0 * (k.gravity[0] * dx + k.gravity[1] * dy + k.gravity[2] * dz) * k.inverseC0Squared;
    const float psi = (rho[j] - rhoI) - hydrostatic - (1.0f - fullnessI * fullness[j]) * (slow[j] - slowI);
    // One division, and the quotient taken whole (finite for the padding's far sentinel).
    rate += w.gradient * (k.mass * approach - diffusion * psi * (rr / (rho[j] * (rr + k.eta2))));
    // The first moment sum_j V_j (x_j - x_i) (x) grad W_ij = -sum_j V_j x_ij x_ij^T (dW/dr) / r.
    const float v = -k.mass * w.gradient / rho[j];
    mxx += v * dx * dx;
    mxy += v * dx * dy;
    mxz += v * dx * dz;
    myy += v * dy * dy;
    myz += v * dy * dz;
    mzz += v * dz * dz;
    // G = sum_j m grad W_ij, the 2 p_i term's sum (pushHighPass).
    const float g = k.mass * w.gradient;
    gx += g * dx;
    gy += g * dy;
    gz += g * dz;
    least = fullness[j] < least ? fullness[j] : least; // the padding's sentinel has fullness 1
  }
  out->densityRate = rate;
  out->moment[0] = mxx;
  out->moment[1] = mxy;
  out->moment[2] = mxz;
  out->moment[3] = myy;
  out->moment[4] = myz;
  out->moment[5] = mzz;
  out->push[0] = gx;
  out->push[1] = gy;
  out->push[2] = gz;
  out->leastFullness = least;
}

PARAFLUID_SIMD_DISPATCH(densityRateInto,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, bool diffuse,
                         float fullnessI, float slowI, const Constants& k, ContinuitySums* out),
                        (in, q, vq, rhoI, diffuse, fullnessI, slowI, k, out), densityRateBody)

/// The continuity sums of one query (the particle or a wall image). fullnessI and slowI: the
/// particle's (densityRateBody).
ContinuitySums densityRate(CandidateBuffer& c, const float q[3], const float vq[3], float rhoI, bool image,
                           float fullnessI, float slowI, const Constants& k)
{
  const PairInput in(c, q, k.h2, image);
  ContinuitySums sums;
  densityRateInto(in, q, vq, rhoI, !image, fullnessI, slowI, k, &sums);
  return sums;
}
} // namespace

void DeltaSPHSolver::updatePressure(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const float rho0 = sim.parameters().restDensity;
  const auto b = static_cast<float>(this->SoundSpeed * this->SoundSpeed * rho0 / kGamma);
  const float inverseRho0 = 1.0f / rho0;
  const auto n = static_cast<std::int64_t>(s.size());
#pragma omp parallel for simd schedule(static) num_threads(threadCount(sim.parameters()))
  for (std::int64_t i = 0; i < n; ++i)
  {
    s.pressure[i] = taitPressure(s.density[i], b, inverseRho0);
  }
}

void DeltaSPHSolver::sumDensityRates(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const Constants k = makeConstants(sim.parameters(), this->SoundSpeed, sim.particleSpacing(),
                                    sim.laplacianCorrection(), this->PressureCorrection);
  this->DensityRate.resize(s.size());
  this->Correction.resize(k.correctGradient ? 6 * s.size() : 0);
  this->NextFullness.resize(s.size());
  this->FullPush.resize(3 * s.size());
  this->Interior.resize(s.size());
  forEachParticleByCell(
    sim.grid(), s, p.smoothingLength, threadCount(p),
    { s.vx.data(), s.vy.data(), s.vz.data(), s.density.data(), this->Fullness.data(), this->SlowDeparture.data() },
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
      float rate = 0.0f, moment[6] = { 0, 0, 0, 0, 0, 0 }, push[3] = { 0, 0, 0 }, least = 1.0f;
      forEachWallImage(position, velocity, p,
                       [&](const float* q, const float* v, const float*, const float* scale, bool image)
                       {
                         const ContinuitySums sums =
                           densityRate(c, q, v, s.density[i], image, this->Fullness[i], this->SlowDeparture[i], k);
                         rate += sums.densityRate;
                         addImageMoment(sums.moment, scale, moment);
                         for (int d = 0; d < 3; ++d)
                         {
                           push[d] += scale[d] * sums.push[d];
                         }
                         least = std::min(least, sums.leastFullness);
                         if (image)
                         {
                           rate += ownImageDensityRate(q, v, position, velocity, k);
                         }
                       });
      this->DensityRate[i] = rate;
      if (k.correctGradient)
      {
        gradientCorrection(moment, k.pressureCorrection, &this->Correction[6 * i]);
      }
      // The neighbours' fullness is a step old, as the diffusion reads it (at the start every
      // particle counts as full until this first pass).
      const SurfaceMeasure surface = measureSurface(moment, least, k.pressureCorrection);
      this->NextFullness[i] = surface.fullness;
      this->Interior[i] = surface.interior;
      for (int d = 0; d < 3; ++d)
      {
        this->FullPush[d * s.size() + i] = this->Interior[i] * push[d];
      }
    },
    sim.ghostFlags()); // a ghost's sums come from its owner (the refreshes below and after the density update)
  // Written after the pass, which reads every neighbour's: the next step's diffusion uses these.
  std::swap(this->Fullness, this->NextFullness);
  const std::size_t n = s.size();
  sim.refreshGhosts({ this->Fullness.data(), this->Interior.data(), this->FullPush.data(), this->FullPush.data() + n,
                      this->FullPush.data() + 2 * n });
  this->CorrectionFresh = true;
}

void DeltaSPHSolver::advanceDensity(SimulationParts& sim, float dt)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  this->sumDensityRates(sim);
  // Written after the pass: the pass reads every neighbour's density of this step.
  const auto n = static_cast<std::int64_t>(s.size());
  float* rho = s.density.data();
  const float* rate = this->DensityRate.data();
#pragma omp parallel for simd schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < n; ++i)
  {
    rho[i] += dt * rate[i];
  }
  if (sim.wall())
  {
    // The mesh's wall moves density with the particle's position, not its velocity: the change of
    // the wall's sum since the last step. Its lattice is the particle's mirror image (moving with
    // the mirrored velocity, p_b = p_i), hence 2 m. Position, not rate: a particle the mesh bounces
    // back gets its compression back, which a rate integrated over the bounce does not give.
    const float twiceMass = 2.0f * p.particleMass;
    const detail::MeshWall& wall = *sim.wall();
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
    for (std::int64_t i = 0; i < n; ++i)
    {
      const float sum = wall.table.at(wall.contacts.distance[i]).sum;
      rho[i] += twiceMass * (sum - this->WallSum[i]);
      this->WallSum[i] = sum;
    }
  }
  this->followSlowDeparture(sim, dt);
  sim.refreshGhosts({ s.density.data(), this->SlowDeparture.data() });
}
} // namespace parafluid::sph
