// Surface tension of Akinci, Akinci & Teschner, "Versatile Surface Tension and Adhesion for SPH
// Fluids" (SIGGRAPH Asia 2013): a cohesion force between pairs, from a kernel that attracts at
// long range and repels at short range (so it does not clump particles), plus a curvature force
// that pulls particles towards the fluid along the difference of their surface normals; each pair
// is weighted by K_ij = 2 rho0 / (rho_i + rho_j), which strengthens it where neighbours are missing.
//
// Units. The paper's gamma is a free coefficient. Here the cohesion is scaled so that the pair
// potential it derives from has the surface energy sigma (Kirkwood & Buff 1949: for a pair
// potential phi of a fluid of number density n, sigma = (pi n^2 / 8) int r^4 phi'(r) dr), which
// makes SurfaceTension a physical value in N/m (water-air 0.0728) at any resolution; the
// curvature term carries the same coefficient times m / h^3 (the dimensionally consistent
// choice; the paper leaves their ratio free).
#include "parafluid/sph/SPHSolver.h"

#include "parafluid/common/Kernels.h"
#include "parafluid/sph/WallMirrors.h"
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
  const std::size_t n = s.size();
  const float h = p.smoothingLength;
  const float m = p.particleMass;
  const float rho0 = p.restDensity;
  // Kirkwood-Buff with phi'(r) = gamma m^2 C(r) and n m = rho0: sigma = pi rho0^2 gamma I / 8.
  const auto gamma = static_cast<float>(8.0 * p.surfaceTension / (kPi * rho0 * rho0 * cohesionMoment(h)));
  const float curvatureScale = gamma / (h * h * h);
  const CubicSplineKernel w(h);
  // Normals n_i = h sum_j m / rho_j grad W_ij: about 1 / 2 long at a flat surface, 0 inside.
  this->Normal.resize(3 * n);
  float* normal = this->Normal.data();
  const float* rho = s.density.data();
  forEachParticleByCell(this->Grid, s, h, threadCount(p), { s.density.data() },
                        [&](CandidateBuffer& c, std::uint32_t i)
                        {
                          const float position[3] = { s.x[i], s.y[i], s.z[i] };
                          float g[3] = { 0.0f, 0.0f, 0.0f };
                          auto add = [&](const float q[3], const float scale[3])
                          {
                            const std::uint32_t count = c.findHits(q, w.h2);
                            for (std::uint32_t k = 0; k < count; ++k)
                            {
                              const std::uint32_t j = c.hits[k];
                              const float r = std::sqrt(c.distanceSquared[j]);
                              if (r <= 0.0f)
                              {
                                continue;
                              }
                              const float f = m / c.channel[0][j] * w.radialDerivative(r) / r;
                              g[0] += scale[0] * f * (q[0] - c.x[j]);
                              g[1] += scale[1] * f * (q[1] - c.y[j]);
                              g[2] += scale[2] * f * (q[2] - c.z[j]);
                            }
                          };
                          static const float ones[3] = { 1.0f, 1.0f, 1.0f };
                          add(position, ones);
                          // Walls are not air: images fill the neighbourhood, so a particle
                          // resting on the floor has no normal towards it.
                          const WallMirrors mirrors = WallMirrors::around(position, p);
                          for (int k = 0; k < mirrors.count; ++k)
                          {
                            float image[3];
                            for (int a = 0; a < 3; ++a)
                            {
                              image[a] = mirrors.scale[k][a] * position[a] + mirrors.offset[k][a];
                            }
                            add(image, mirrors.scale[k]);
                          }
                          for (int a = 0; a < 3; ++a)
                          {
                            normal[3 * i + a] = h * g[a];
                          }
                        });
  // Forces between real particles only: an image across a wall is not fluid that pulls.
  forEachParticleByCell(
    this->Grid, s, h, threadCount(p), { s.density.data(), normal, normal + 1, normal + 2 },
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      (void)normal;
      const float q[3] = { s.x[i], s.y[i], s.z[i] };
      const float ni[3] = { normal[3 * i], normal[3 * i + 1], normal[3 * i + 2] };
      const std::uint32_t count = c.findHits(q, w.h2);
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
          a[d] -= weight * (pull * x + curvatureScale * m * (ni[d] - c.channel[1 + d][j]));
        }
      }
      s.ax[i] += a[0];
      s.ay[i] += a[1];
      s.az[i] += a[2];
    });
}
} // namespace parafluid::sph
