// δ-SPH's momentum: the pressure gradient (corrected, with the push's high pass), Monaghan's
// artificial viscosity, the laminar term and the wall images' and the mesh wall's pushes.
#include "parafluid/sph/DeltaSPHSolver.h"

#include "parafluid/common/SimdDispatch.h"
#include "private/DeltaSPHMomentum.h"
#include "private/DeltaSPHOwnImage.h"
#include "private/DeltaSPHPairs.h"
#include "private/GradientCorrection.h"
#include "private/MeshWall.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"
#include "private/WallImages.h"

namespace parafluid::sph
{
using detail::applyGradientCorrection;
using detail::forEachParticleByCell;
using detail::forEachWallImage;
using detail::threadCount;
using namespace delta;

namespace
{
/// What the force pass sums over one query's neighbours.
struct ForceSums
{
  float a[3] = { 0, 0, 0 };           // the momentum terms' acceleration [m/s^2]
  float difference[3] = { 0, 0, 0 };  // sum_j m (p_j - p_i) / (rho_i rho_j) grad W_ij
  float shepard = 0.0f;               // sum_j V_j W_ij
  float shepardPush[3] = { 0, 0, 0 }; // sum_j V_j W_ij FullPush_j (x, y, z)
};

/// The momentum terms of particle i (position q, velocity vq, density and pressure) against the
/// candidates: pressure, tensile correction, artificial and laminar viscosity. `t` turns the
/// laminar term's relative velocity into that of a no-slip wall image (all ones and not read
/// without NoSlipImage); `lift` is read only with Lift (a wall image's query: the particle's own
/// neighbours have none, and skipping it saves four multiply-adds a pair).
template<bool Laminar, bool NoSlipImage, bool Lift>
__attribute__((always_inline)) inline void forceTermsBody(const PairInput& in, const float* q, const float* vq,
                                                          float rhoI, float pI, const float* t, const float* lift,
                                                          const Constants& k, ForceSums* out)
{
  const std::uint32_t count = in.count;
  const float *px = in.px, *py = in.py, *pz = in.pz;
  const float *vx = in.vx, *vy = in.vy, *vz = in.vz;
  const float *rho = in.rho, *pressure = in.pressure;
  const std::uint32_t* hits = in.hits;
  const float inverseRhoI = 1.0f / rhoI;
  const float termI = pI * inverseRhoI * inverseRhoI;
  const float tensileI = pI < 0.0f ? -kTensileCoefficient * termI : 0.0f;
  const float massOverRhoI = k.mass * inverseRhoI;
  const float *pushX = in.slowDeparture, *pushY = in.pushY, *pushZ = in.pushZ;
  float ax = 0.0f, ay = 0.0f, az = 0.0f, bx = 0.0f, by = 0.0f, bz = 0.0f;
  float sw = 0.0f, sx = 0.0f, sy = 0.0f, sz = 0.0f;
#pragma omp simd reduction(+ : ax, ay, az, bx, by, bz, sw, sx, sy, sz)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const float rr = dx * dx + dy * dy + dz * dz; // computed: a gather of the search's r^2 costs more
    const WendlandPair w(k.w, __builtin_sqrtf(rr));
    // A wall image's pressure, extrapolated hydrostatically from its particle's (lift: 0 for real
    // neighbours and without the gradient correction; see detail::hydrostaticImageLift).
    const float pJ =
      Lift ? pressure[j] + rho[j] * (lift[0] * px[j] + lift[1] * py[j] + lift[2] * pz[j] + lift[3]) : pressure[j];
    float laminar = 0.0f, inverseRhoJ;
    const float scalar = momentumFactor<Laminar>(dx, dy, dz, rr, w.value, vq, vx[j], vy[j], vz[j], rhoI, termI,
                                                 tensileI, rho[j], pJ, k, &laminar, &inverseRhoJ) *
                         (k.mass * w.gradient); // the product first, as before the factor was shared
    ax += scalar * dx;
    ay += scalar * dy;
    az += scalar * dz;
    const float difference = (pJ - pI) * (massOverRhoI * inverseRhoJ) * w.gradient;
    bx += difference * dx;
    by += difference * dy;
    bz += difference * dz;
    // The Shepard mean of the neighbours' FullPush for the push's high pass (pushHighPass).
    const float smoothing = k.mass * inverseRhoJ * w.value;
    sw += smoothing;
    sx += smoothing * pushX[j];
    sy += smoothing * pushY[j];
    sz += smoothing * pushZ[j];
    if constexpr (Laminar)
    {
      float wx, wy, wz;
      laminarVelocity<NoSlipImage>(vq, vx[j], vy[j], vz[j], t, wx, wy, wz);
      const float viscous = laminar * (k.mass * w.gradient);
      ax += viscous * wx;
      ay += viscous * wy;
      az += viscous * wz;
    }
  }
  out->a[0] = ax;
  out->a[1] = ay;
  out->a[2] = az;
  out->difference[0] = bx;
  out->difference[1] = by;
  out->difference[2] = bz;
  out->shepard = sw;
  out->shepardPush[0] = sx;
  out->shepardPush[1] = sy;
  out->shepardPush[2] = sz;
}

// The pair loops compiled for AVX-512, AVX2 and the baseline, the widest this CPU runs picked
// at each call (parafluid/common/SimdDispatch.h).
PARAFLUID_SIMD_DISPATCH(laminarForceTerms,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, float pI, const float* t,
                         const float* lift, const Constants& k, ForceSums* out),
                        (in, q, vq, rhoI, pI, t, lift, k, out), (forceTermsBody<true, true, true>))
PARAFLUID_SIMD_DISPATCH(laminarInteriorForceTerms,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, float pI, const float* t,
                         const float* lift, const Constants& k, ForceSums* out),
                        (in, q, vq, rhoI, pI, t, lift, k, out), (forceTermsBody<true, false, false>))
PARAFLUID_SIMD_DISPATCH(inviscidForceTerms,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, float pI, const float* t,
                         const float* lift, const Constants& k, ForceSums* out),
                        (in, q, vq, rhoI, pI, t, lift, k, out), (forceTermsBody<false, false, true>))

template<bool Laminar>
ForceSums forceTerms(CandidateBuffer& c, const float q[3], const float vq[3], float rhoI, float pI, const float t[3],
                     const float lift[4], bool image, const Constants& k)
{
  const PairInput in(c, q, k.h2, image);
  ForceSums sums;
  if constexpr (Laminar)
  {
    // The particle itself (t all ones) skips the no-slip image's velocity product.
    if (image)
      laminarForceTerms(in, q, vq, rhoI, pI, t, lift, k, &sums);
    else
      laminarInteriorForceTerms(in, q, vq, rhoI, pI, t, lift, k, &sums);
  }
  else
    inviscidForceTerms(in, q, vq, rhoI, pI, t, lift, k, &sums);
  return sums;
}

template<bool Laminar>
void forcePass(const NeighbourGrid& grid, ParticleState& s, const SPHParameters& p, const Constants& k,
               const detail::MeshWall* wall, const float* correction, const float* push, const float* interior,
               const std::uint8_t* ghosts)
{
  const std::size_t n = s.size();
  forEachParticleByCell(
    grid, s, p.smoothingLength, threadCount(p),
    { s.vx.data(), s.vy.data(), s.vz.data(), s.density.data(), s.pressure.data(), push, push + n, push + 2 * n },
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
      float a[3] = { p.gravity[0], p.gravity[1], p.gravity[2] };
      float difference[3] = { 0.0f, 0.0f, 0.0f };
      float shepard = 0.0f, shepardPush[3] = { 0.0f, 0.0f, 0.0f };
      forEachWallImage(position, velocity, p,
                       [&](const float* q, const float* v, const float* t, const float* scale, bool image)
                       {
                         float lift[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
                         if (image && k.correctGradient)
                         {
                           // Without the lift the image of every neighbour has that neighbour's
                           // pressure, so the pressure field is even across a floor and a floor
                           // layer's neighbours and their images push it equally up and down: at
                           // rest it was held up by its own image's pair alone.
                           detail::hydrostaticImageLift(q, position, scale, k.gravity, lift);
                         }
                         ForceSums g = forceTerms<Laminar>(c, q, v, s.density[i], s.pressure[i], t, lift, image, k);
                         if (image)
                         {
                           addOwnImageForce<Laminar>(q, v, t, position, velocity, s.density[i], s.pressure[i], k, g.a);
                         }
                         for (int d = 0; d < 3; ++d)
                         {
                           a[d] += scale[d] * g.a[d];
                           difference[d] += scale[d] * g.difference[d];
                           shepardPush[d] += scale[d] * g.shepardPush[d];
                         }
                         shepard += g.shepard;
                       });
      if (k.highPass && shepard > 0.0f)
      {
        // The symmetric form's -2 C p_i / rho_i^2 G_i less its smooth part: + 2 C p_i / rho_i^2
        // times the Shepard mean of the neighbours' Interior-weighted G, where i is inside the
        // fluid (SPHParameters::pushHighPass). The mean is over the wall images too, mirrored, so
        // a wall's own-image push (odd across the wall) survives it.
        const float rho = s.density[i];
        const float factor = 2.0f * k.pressureCorrection * s.pressure[i] / (rho * rho) * interior[i] / shepard;
        for (int d = 0; d < 3; ++d)
        {
          a[d] += factor * shepardPush[d];
        }
      }
      if (correction)
      {
        // The momentum sum holds -C sum_j m (p_j - p_i) / (rho_i rho_j) grad W_ij among its terms;
        // corrected, that part is -L times the sum (gradientCorrection: L - C I).
        applyGradientCorrection(correction + 6 * static_cast<std::size_t>(i), difference, a);
      }
      detail::MeshWallTable::Weight weight;
      const float* normal = nullptr;
      if (wall && wall->of(i, weight, normal))
      {
        // The mesh's lattice is the particle's mirror image: p_b = p_i, negative
        // too (a wall that only pushed would take in energy wherever the water
        // is in tension, as a film spreading over a terrain is).
        const float rho = s.density[i];
        const float term = s.pressure[i] / (rho * rho);
        const float scalar = -2.0f * k.pressureCorrection * term * k.mass * weight.slope;
        for (int d = 0; d < 3; ++d)
        {
          a[d] += scalar * normal[d];
        }
      }
      s.ax[i] = a[0];
      s.ay[i] = a[1];
      s.az[i] = a[2];
    },
    ghosts);
}
} // namespace

void DeltaSPHSolver::computeAccelerations(SimulationParts& sim)
{
  const Constants k = makeConstants(sim.parameters(), this->SoundSpeed, sim.particleSpacing(),
                                    sim.laplacianCorrection(), this->PressureCorrection);
  if (!this->CorrectionFresh)
  {
    // At the start (the step sums these with the density rates). FullPush is summed and gathered
    // even with pushHighPass off: the force pass's loop reads it either way.
    this->sumDensityRates(sim);
  }
  const float* correction = k.correctGradient ? this->Correction.data() : nullptr;
  // A ghost's acceleration is never read: it goes with the ghosts after the step.
  if (sim.parameters().kinematicViscosity > 0.0f || sim.parameters().viscosity > 0.0f)
  {
    forcePass<true>(sim.grid(), sim.state(), sim.parameters(), k, sim.wall(), correction, this->FullPush.data(),
                    this->Interior.data(), sim.ghostFlags());
  }
  else
  {
    forcePass<false>(sim.grid(), sim.state(), sim.parameters(), k, sim.wall(), correction, this->FullPush.data(),
                     this->Interior.data(), sim.ghostFlags());
  }
  this->CorrectionFresh = false;
  sim.addSurfaceTension();
}
} // namespace parafluid::sph
