// Müller et al. (2003) forces: spiky pressure gradient, viscosity-kernel Laplacian and colour-field
// surface tension, plus the physical (laminar) viscosity: the forces of Müller's WCSPH, whose
// pressure joins the same pair sums, and the explicit non-pressure forces of DFSPH.
#include "parafluid/sph/SPHSolver.h"

#include "parafluid/common/Kernels.h"
#include "parafluid/sph/WallMirrors.h"
#include "private/MullerPairs.h"
#include "private/NeighbourCandidates.h"

#include <algorithm>
#include <cmath>

namespace parafluid::sph
{
using detail::CandidateBuffer;
using detail::forEachParticleByCell;
using detail::threadCount;

namespace
{
struct PairSums
{
  float force[3] = { 0, 0, 0 };   // pressure (+ viscosity), per unit of the query's density
  float viscous[3] = { 0, 0, 0 }; // viscosity when summed apart, per unit of the query's density
  float normal[3] = { 0, 0, 0 };  // Σ (h² − r²)² r_ij / rho_j       (colour gradient, unscaled)
  float laplacian = 0.0f;         // Σ (h² − r²)(3h² − 7r²) / rho_j  (colour Laplacian, unscaled)
};

// Candidate channels of the force pass.
enum Channel
{
  VX,
  VY,
  VZ,
  PRESSURE,
  INVERSE_DENSITY
};

/// Pair sums for a query particle (position q, velocity v, pressure pi) over the candidates:
///   pressure:   Σ_j P (pi + pj)/rho_j (h − r)² / r · (q − x_j)
///   viscosity:  Σ_j V / rho_j (h − r) (v_j − v)
///   laminar:    Σ_j L / rho_j ((v − v_j) . T (q − x_j)) / (r² + η²) (h − r)² / r (q − x_j), the
///               operator of Monaghan (2005) with the spiky gradient; T turns the relative velocity
///               into that of a no-slip wall image (see accelerationPass), all ones otherwise
///   colour field gradient and Laplacian (poly6, without constants).
/// Each term is compiled in only when its flag is set, so a scene without it does not pay for it.
/// The viscous sum goes into `force` unless SeparateViscous (no-slip wall images map it back
/// differently from the pressure sum).
template<bool Pressure, bool Viscosity, bool Tension, bool SeparateViscous = false>
PairSums pairSums(CandidateBuffer& c, const float q[3], const float v[3], float pi, const detail::MullerConstants& k,
                  const float t[3])
{
  const std::uint32_t count = c.findHits(q, k.h2);
  const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data();
  const float *pvx = c.channel[VX].data(), *pvy = c.channel[VY].data(), *pvz = c.channel[VZ].data();
  const float *pp = c.channel[PRESSURE].data(), *pinv = c.channel[INVERSE_DENSITY].data();
  const float* r2 = c.distanceSquared.data();
  const std::uint32_t* hits = c.hits.data();
  float fx = 0.0f, fy = 0.0f, fz = 0.0f, gx = 0.0f, gy = 0.0f, gz = 0.0f;
  float nx = 0.0f, ny = 0.0f, nz = 0.0f, lap = 0.0f;
#pragma omp simd reduction(+ : fx, fy, fz, gx, gy, gz, nx, ny, nz, lap)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const std::uint32_t j = hits[n];
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    if constexpr (Pressure || Viscosity)
    {
      const float dist = std::sqrt(r2[j]);
      const float w = k.h - dist;
      if constexpr (Pressure)
      {
        const float pair = detail::mullerPressurePair(k, pi, pp[j], pinv[j], w, dist);
        fx += pair * dx;
        fy += pair * dy;
        fz += pair * dz;
      }
      if constexpr (Viscosity)
      {
        // The laminar term points along the pair, like pressure, and maps back like it.
        const float approach = t[0] * (v[0] - pvx[j]) * dx + t[1] * (v[1] - pvy[j]) * dy + t[2] * (v[2] - pvz[j]) * dz;
        const float laminar = detail::mullerLaminarPair(k, approach, r2[j], pinv[j], w, dist);
        fx += laminar * dx;
        fy += laminar * dy;
        fz += laminar * dz;
        const float pair = detail::mullerViscousPair(k, pinv[j], w);
        if constexpr (SeparateViscous)
        {
          gx += pair * (pvx[j] - v[0]);
          gy += pair * (pvy[j] - v[1]);
          gz += pair * (pvz[j] - v[2]);
        }
        else
        {
          fx += pair * (pvx[j] - v[0]);
          fy += pair * (pvy[j] - v[1]);
          fz += pair * (pvz[j] - v[2]);
        }
      }
    }
    if constexpr (Tension)
    {
      const float d = k.h2 - r2[j];
      const float g = pinv[j] * d * d;
      nx += g * dx;
      ny += g * dy;
      nz += g * dz;
      lap += pinv[j] * d * (3.0f * k.h2 - 7.0f * r2[j]); // the particle itself counts here (r = 0)
    }
  }
  PairSums sums;
  sums.force[0] = fx;
  sums.force[1] = fy;
  sums.force[2] = fz;
  sums.viscous[0] = gx;
  sums.viscous[1] = gy;
  sums.viscous[2] = gz;
  sums.normal[0] = nx;
  sums.normal[1] = ny;
  sums.normal[2] = nz;
  sums.laplacian = lap;
  return sums;
}

template<bool Pressure, bool Viscosity, bool Tension>
void accelerationPass(const NeighbourGrid& grid, ParticleState& s, const SPHParameters& p, const float* inverseDensity,
                      float gradientCorrection, float laplacianCorrection, const std::uint8_t* ghosts)
{
  const detail::MullerConstants k = detail::mullerConstants(p, Pressure, gradientCorrection, laplacianCorrection);

  forEachParticleByCell(
    grid, s, k.h, detail::threadCount(p), { s.vx.data(), s.vy.data(), s.vz.data(), s.pressure.data(), inverseDensity },
    [&](CandidateBuffer& candidates, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
      const float pi = s.pressure[i];
      static const float ones[3] = { 1.0f, 1.0f, 1.0f };
      PairSums sum = pairSums<Pressure, Viscosity, Tension>(candidates, position, velocity, pi, k, ones);
      // Mirror images: the pair term of x_i with R x_j equals R times the term of R x_i with x_j
      // (R is a reflection, its own inverse); scalars are unchanged. An image's velocity is S v_j
      // (S diagonal, +-1): sum w (S v_j - v_i) = S sum w (v_j - S v_i), so the query moves with
      // S v_i and the viscous sum maps back with S.
      const WallMirrors mirrors = WallMirrors::around(position, p, true);
      for (int m = 0; m < mirrors.count; ++m)
      {
        float image[3], imageVelocity[3], t[3];
        mirrors.image(m, position, image);
        for (int a = 0; a < 3; ++a)
        {
          imageVelocity[a] = mirrors.velocityScale[m][a] * velocity[a];
          t[a] = mirrors.velocityScale[m][a] * mirrors.scale[m][a];
        }
        // Free-slip images (S = R) keep the one combined sum; no-slip ones sum viscosity apart.
        const PairSums g = mirrors.noSlip(m)
                             ? pairSums<Pressure, Viscosity, Tension, true>(candidates, image, imageVelocity, pi, k, t)
                             : pairSums<Pressure, Viscosity, Tension>(candidates, image, imageVelocity, pi, k, t);
        for (int a = 0; a < 3; ++a)
        {
          sum.force[a] += mirrors.scale[m][a] * g.force[a];
          sum.viscous[a] += mirrors.velocityScale[m][a] * g.viscous[a];
          sum.normal[a] += mirrors.scale[m][a] * g.normal[a];
        }
        sum.laplacian += g.laplacian;
      }
      const float inv = inverseDensity[i];
      float a[3] = { (sum.force[0] + sum.viscous[0]) * inv + p.gravity[0],
                     (sum.force[1] + sum.viscous[1]) * inv + p.gravity[1],
                     (sum.force[2] + sum.viscous[2]) * inv + p.gravity[2] };
      if constexpr (Tension)
      {
        detail::addColourFieldTension(k, sum.normal, sum.laplacian, inv, a);
      }
      s.ax[i] = a[0];
      s.ay[i] = a[1];
      s.az[i] = a[2];
    },
    ghosts);
}

using Pass = void (*)(const NeighbourGrid&, ParticleState&, const SPHParameters&, const float*, float, float,
                      const std::uint8_t*);
template<bool Pressure>
Pass choosePass(bool viscosity, bool tension)
{
  if (viscosity)
  {
    return tension ? accelerationPass<Pressure, true, true> : accelerationPass<Pressure, true, false>;
  }
  return tension ? accelerationPass<Pressure, false, true> : accelerationPass<Pressure, false, false>;
}
} // namespace

void SPHSolver::computeAccelerations(bool withPressure)
{
  ParticleState& s = this->State;
  const SPHParameters& p = this->Parameters;
  // Müller's viscosity, and (WCSPH) the explicit laminar term; DFSPH's laminar term is implicit.
  const bool viscosity = p.viscosity > 0.0f || (withPressure && p.kinematicViscosity > 0.0f);
  const bool tension = p.surfaceTension > 0.0f && p.surfaceTensionModel == SurfaceTensionModel::ColourField;
  const std::size_t n = s.size();
  const int threads = threadCount(p);
  if (this->Ghosts)
  {
    // Each ghost's summed density is cut where this process's particles end: its owner's counts.
    this->Ghosts->refresh({ s.density.data(), s.pressure.data() });
  }
  if (!withPressure && !viscosity && !tension)
  {
    // Nothing between particles: gravity alone, no neighbour pass.
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
    {
      s.ax[i] = p.gravity[0];
      s.ay[i] = p.gravity[1];
      s.az[i] = p.gravity[2];
    }
    this->addSurfaceTension();
    return;
  }
  this->InverseDensity.resize(n);
  float* inverseDensity = this->InverseDensity.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
  {
    inverseDensity[i] = 1.0f / s.density[i]; // density > 0: every particle counts itself
  }
  const Pass pass = withPressure ? choosePass<true>(viscosity, tension) : choosePass<false>(viscosity, tension);
  // A ghost's acceleration is never read: it goes with the ghosts after the step.
  pass(this->Grid, s, p, inverseDensity, this->SpikyGradientCorrection, this->LaplacianCorrection, this->ghostFlags());
  this->addSurfaceTension();
}
} // namespace parafluid::sph
