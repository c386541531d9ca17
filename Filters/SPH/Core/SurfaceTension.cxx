// Surface tension of Akinci, Akinci & Teschner, "Versatile Surface Tension and Adhesion for SPH
// Fluids" (SIGGRAPH Asia 2013), its cohesion force: pairs attract at long range and repel at short
// range (so particles do not clump), each pair weighted by K_ij = 2 rho0 / (rho_i + rho_j), which
// strengthens it where neighbours are missing, at the surface.
//
// Units. The paper's gamma is a free coefficient. Here it is scaled so that the pair potential the
// cohesion derives from has the surface energy sigma (Kirkwood & Buff 1949: for a pair potential
// phi of a fluid of number density n, sigma = (pi n^2 / 8) int r^4 phi'(r) dr), which makes
// SurfaceTension a physical value in N/m (water-air 0.0728) at any resolution.
//
// The paper's second term, a curvature force -gamma sum_j K_ij (n_i - n_j) along the difference of
// surface normals, is left out: its weight relative to the cohesion is free in the paper, and every
// weight tried, from the dimensional one (gamma m / h^3) down to 1/500 of it, blew a weightless
// 5 mm cube up within 12 ms, while the cohesion alone pulls the cube round and stays stable. (Later
// probe: with the paper's normal, which points into the water, the term is stable; the opposite one
// anti-diffuses short waves. What is missing is its share of sigma: at the paper's weight a drop
// oscillated as at 3.9 sigma. Testing/Benchmarks/README.md, "Akinci's curvature term".)
#include "parafluid/sph/SPHSolver.h"

#include "parafluid/common/Kernels.h"
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
/// Akinci's cohesion kernel C(r) = 32 / (pi h^9) { (h - r)^3 r^3 for h/2 < r <= h;
/// 2 (h - r)^3 r^3 - h^6 / 64 for 0 < r <= h/2 } (negative = repulsive at short range).
float cohesion(float r, float h)
{
  if (r >= h || r <= 0.0f)
  {
    return 0.0f;
  }
  const float c = 32.0f / (kPiF * std::pow(h, 9.0f));
  const float d = (h - r) * (h - r) * (h - r) * r * r * r;
  return r > 0.5f * h ? c * d : c * (2.0f * d - std::pow(h, 6.0f) / 64.0f);
}

/// int_0^h r^4 C(r) dr, by Simpson's rule (C is a polynomial on each half: exact enough).
double cohesionMoment(float h)
{
  const int n = 2000;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k)
  {
    const double r = h * static_cast<double>(k) / n;
    const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += weight * r * r * r * r * cohesion(static_cast<float>(r), h);
  }
  return sum * h / (3.0 * n);
}
} // namespace

void SPHSolver::addSurfaceTension()
{
  const SPHParameters& p = this->Parameters;
  if (!(p.surfaceTension > 0.0f) || p.surfaceTensionModel != SurfaceTensionModel::Akinci)
  {
    return;
  }
  ParticleState& s = this->State;
  const float h = p.smoothingLength;
  const float m = p.particleMass;
  const float rho0 = p.restDensity;
  // Kirkwood-Buff with phi'(r) = gamma m^2 C(r) and n m = rho0: sigma = pi rho0^2 gamma I / 8.
  const auto gamma = static_cast<float>(8.0 * p.surfaceTension / (kPi * rho0 * rho0 * cohesionMoment(h)));
  const float* rho = s.density.data();
  // Forces between real particles only: an image across a wall is not fluid that pulls.
  forEachParticleByCell(this->Grid, s, h, threadCount(p), { s.density.data() },
                        [&](CandidateBuffer& c, std::uint32_t i)
                        {
                          const float q[3] = { s.x[i], s.y[i], s.z[i] };
                          const std::uint32_t count = c.findHits(q, h * h);
                          float a[3] = { 0.0f, 0.0f, 0.0f };
                          for (std::uint32_t k = 0; k < count; ++k)
                          {
                            const std::uint32_t j = c.hits[k];
                            const float r = std::sqrt(c.distanceSquared[j]);
                            if (r <= 0.0f)
                            {
                              continue;
                            }
                            const float weight = 2.0f * rho0 / (rho[i] + c.channel[0][j]);
                            const float pull = gamma * m * cohesion(r, h) / r;
                            for (int d = 0; d < 3; ++d)
                            {
                              const float x = q[d] - (d == 0 ? c.x[j] : d == 1 ? c.y[j] : c.z[j]);
                              a[d] -= weight * pull * x;
                            }
                          }
                          s.ax[i] += a[0];
                          s.ay[i] += a[1];
                          s.az[i] += a[2];
                        });
}
} // namespace parafluid::sph
