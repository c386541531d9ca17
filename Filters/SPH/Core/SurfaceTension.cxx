// Surface tension of Akinci, Akinci & Teschner, "Versatile Surface Tension and Adhesion for SPH
// Fluids" (SIGGRAPH Asia 2013). Two terms, each pair weighted by K_ij = 2 rho0 / (rho_i + rho_j),
// which strengthens it where neighbours are missing:
// - cohesion: pairs attract at long range and repel at short range (so particles do not clump);
// - curvature: a_i -= gamma sum_j K_ij (n_i - n_j), n_i = h sum_j (m / rho_j) grad_i W_ij the
//   surface normal, which points into the fluid (with the opposite normal the term grows short
//   waves and blows up). It pulls a bulge in, a hollow out: it minimises curvature.
//
// Units. The paper's gamma is a free coefficient, the same number for both terms (in SI units: the
// cohesion's gamma m_j C(r) and the curvature's gamma (n_i - n_j) differ by the units of a
// density, so the terms' split of sigma depends on rho0, not on the particle size). Here gamma is
// scaled so that the two terms together have the surface tension sigma of a flat interface in the
// continuum limit (a uniform fluid up to the interface, K_ij = 1):
// - the cohesion derives from a pair potential phi'(r) = gamma m^2 C(r), whose surface tension is
//   Kirkwood & Buff's (1949) sigma = (pi n^2 / 8) int r^4 phi'(r) dr;
// - the curvature term's force is not central; its surface tension is the mechanical one,
//   sigma = int (P_N - P_T) dz, from the force the fluid below a plane exerts on the fluid above
//   it (Irving & Kirkwood 1950), integrated over the plane's height (curvatureShare below).
// With Wendland C2 at 3 spacings (about δ-SPH's 2.9) the curvature term carries 3.13 times the cohesion's
// share, with the cubic spline at 2 spacings (DFSPH) 0.91 times. Nothing is fitted: the oscillating
// drop (Testing/SPH/Validation/Drop.cxx, in ctest and ParaFluidSPHValidation) checks the sum
// against Rayleigh's period: within 0.2-1.9 % with δ-SPH at 8-14 particles over the radius.
// SurfaceTensionModel::AkinciCohesion keeps the cohesion alone, scaled by itself; a drop's
// deformation then dies out within a quarter period instead of oscillating.
#include "parafluid/sph/SPHSolver.h"

#include "parafluid/common/Kernels.h"
#include "private/AkinciTension.h"
#include "private/AnyKernel.h"
#include "private/NeighbourCandidates.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace parafluid::sph
{
using detail::CandidateBuffer;
using detail::CohesionKernel;
using detail::forEachParticleByCell;
using detail::threadCount;

namespace
{
/// Simpson's rule of f over [a, b] with n (even) intervals.
template<class F>
double simpson(F&& f, double a, double b, int n)
{
  double sum = 0.0;
  for (int k = 0; k <= n; ++k)
  {
    const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += weight * f(a + (b - a) * k / n);
  }
  return sum * (b - a) / (3.0 * n);
}

/// int_0^h r^4 C(r) dr (C is a polynomial on each half: exact enough).
double cohesionMoment(float h)
{
  const CohesionKernel cohesion(h);
  return simpson([&cohesion](double r) { return r * r * r * r * cohesion(static_cast<float>(r)); }, 0.0, h, 2000);
}

/// (dW/dr) / r of a density kernel from r^2, so that grad_i W_ij = this times (x_i - x_j); 0 at
/// r = 0, where it multiplies a zero vector.
struct WendlandGradient
{
  WendlandC2Kernel w;
  float operator()(float r2) const { return w.gradientFactor(std::sqrt(r2)); }
};
struct CubicGradient
{
  CubicSplineKernel w;
  float operator()(float r2) const
  {
    const float r = std::sqrt(r2);
    return r > 0.0f ? w.radialDerivative(r) / r : 0.0f;
  }
};
struct Poly6Gradient
{
  Poly6Kernel w;
  float operator()(float r2) const { return w.gradientFactorFromSquared(r2); }
};

/// The curvature term's surface tension over the cohesion's, both per unit gamma, on a flat
/// interface of a uniform fluid (z < 0, number density n = rho0 / m). There the normal is
/// n(z) = -h W1(z) z^, with W1(z) = 2 pi int_|z|^h W(r) r dr the kernel integrated over a plane,
/// and the element at y pushes the element at x with gamma m n^2 h (W1(z_x) - W1(z_y)) along z
/// wherever |x - y| < h. The surface tension is the sum over pairs of their separation in z times
/// that force, halved (each pair counted from both ends), over the disc of radius
/// sqrt(h^2 - dz^2) at each separation dz: sigma_curvature = gamma rho0^2 h J / (2 m). Below
/// z = -2h no pair has a force.
double curvatureShare(DensityKernel kernel, float h, float m, float rho0, double cohesionIntegral)
{
  const detail::AnyKernel w(kernel, h);
  const int cells = 240;
  const double dz = 2.0 * h / cells;
  std::vector<double> z(cells), w1(cells);
  for (int k = 0; k < cells; ++k)
  {
    z[k] = -(k + 0.5) * dz;
    const double from = std::min(std::fabs(z[k]), static_cast<double>(h));
    w1[k] = 2.0 * kPi *
            simpson([&w](double r) { return r * w.value(static_cast<float>(r)); }, from, static_cast<double>(h), 200);
  }
  double j = 0.0;
  for (int a = 0; a < cells; ++a)
  {
    for (int b = 0; b < cells; ++b)
    {
      const double separation = z[a] - z[b];
      if (std::fabs(separation) < h)
      {
        j += separation * (w1[a] - w1[b]) * kPi * (h * h - separation * separation);
      }
    }
  }
  j *= dz * dz;
  const double curvatureSigma = rho0 * rho0 * h * j / (2.0 * m);           // per unit gamma
  const double cohesionSigma = kPi * rho0 * rho0 * cohesionIntegral / 8.0; // per unit gamma
  return curvatureSigma / cohesionSigma;
}
} // namespace

float detail::akinciGamma(const SPHParameters& p)
{
  // Kirkwood-Buff with phi'(r) = gamma m^2 C(r) and n m = rho0: sigma = pi rho0^2 gamma I / 8,
  // shared with the curvature term in proportion to their surface tensions per unit gamma.
  const float h = p.smoothingLength, m = p.particleMass, rho0 = p.restDensity;
  const double moment = cohesionMoment(h);
  const double curvature =
    p.surfaceTensionModel == SurfaceTensionModel::Akinci ? curvatureShare(p.densityKernel(), h, m, rho0, moment) : 0.0;
  return static_cast<float>(8.0 * p.surfaceTension / (kPi * rho0 * rho0 * moment * (1.0 + curvature)));
}

void SPHSolver::computeSurfaceNormals()
{
  ParticleState& s = this->State;
  const SPHParameters& p = this->Parameters;
  const float h = p.smoothingLength;
  const float m = p.particleMass;
  for (auto& normal : this->SurfaceNormal)
  {
    normal.resize(s.size());
  }
  float* normal[3] = { this->SurfaceNormal[0].data(), this->SurfaceNormal[1].data(), this->SurfaceNormal[2].data() };
  // The kernel is chosen once, outside the pair loop.
  const auto sum = [&](const auto& gradientFactor)
  {
    forEachParticleByCell(this->Grid, s, h, threadCount(p), { s.density.data() },
                          [&](CandidateBuffer& c, std::uint32_t i)
                          {
                            const float q[3] = { s.x[i], s.y[i], s.z[i] };
                            const std::uint32_t count = c.findHits(q, h * h);
                            float g[3] = { 0.0f, 0.0f, 0.0f };
                            for (std::uint32_t k = 0; k < count; ++k)
                            {
                              const std::uint32_t j = c.hits[k];
                              const float f = m / c.channel[0][j] * gradientFactor(c.distanceSquared[j]);
                              g[0] += f * (q[0] - c.x[j]);
                              g[1] += f * (q[1] - c.y[j]);
                              g[2] += f * (q[2] - c.z[j]);
                            }
                            for (int a = 0; a < 3; ++a)
                            {
                              normal[a][i] = h * g[a];
                            }
                          });
  };
  switch (p.densityKernel())
  {
    case DensityKernel::WendlandC2:
      sum(WendlandGradient{ WendlandC2Kernel(h) });
      break;
    case DensityKernel::CubicSpline:
      sum(CubicGradient{ CubicSplineKernel(h) });
      break;
    default:
      sum(Poly6Gradient{ Poly6Kernel(h) });
  }
  if (this->Ghosts)
  {
    this->Ghosts->refresh({ normal[0], normal[1], normal[2] });
  }
}

void SPHSolver::addSurfaceTension()
{
  const SPHParameters& p = this->Parameters;
  const bool withCurvature = p.surfaceTensionModel == SurfaceTensionModel::Akinci;
  if (!(p.surfaceTension > 0.0f) || !(withCurvature || p.surfaceTensionModel == SurfaceTensionModel::AkinciCohesion))
  {
    return;
  }
  ParticleState& s = this->State;
  const float h = p.smoothingLength;
  const float m = p.particleMass;
  const float rho0 = p.restDensity;
  // Computed once for a set of parameters: the integrals cost as much as a small scene's pass.
  const std::array<float, 6> key = { static_cast<float>(p.surfaceTensionModel), p.surfaceTension, h, m, rho0,
                                     static_cast<float>(p.densityKernel()) };
  if (key != this->AkinciGammaKey)
  {
    this->AkinciGamma = detail::akinciGamma(p);
    this->AkinciGammaKey = key;
  }
  const float gamma = this->AkinciGamma;
  if (withCurvature)
  {
    this->computeSurfaceNormals();
  }
  const CohesionKernel cohesion(h);
  const float* rho = s.density.data();
  const float* normal[3] = { this->SurfaceNormal[0].data(), this->SurfaceNormal[1].data(),
                             this->SurfaceNormal[2].data() };
  const float pullScale = gamma * m;
  // Forces between real particles only: an image across a wall is not fluid that pulls. The
  // candidates carry the normals only when the curvature term reads them. A particle's own entry
  // (r = 0) adds nothing: its 1/r is taken as 0, and n_i - n_i = 0.
  const auto pass = [&](CandidateBuffer& c, std::uint32_t i)
  {
    const float q[3] = { s.x[i], s.y[i], s.z[i] };
    const float n[3] = { withCurvature ? normal[0][i] : 0.0f, withCurvature ? normal[1][i] : 0.0f,
                         withCurvature ? normal[2][i] : 0.0f };
    const std::uint32_t count = c.findHits(q, h * h);
    const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data(), *r2 = c.distanceSquared.data();
    const float* rhoJ = c.channel[0].data();
    const std::uint32_t* hits = c.hits.data();
    const float rhoI = rho[i];
    float ax = 0.0f, ay = 0.0f, az = 0.0f;
    if (withCurvature)
    {
      const float *nx = c.channel[1].data(), *ny = c.channel[2].data(), *nz = c.channel[3].data();
#pragma omp simd reduction(+ : ax, ay, az)
      for (std::uint32_t k = 0; k < count; ++k)
      {
        const std::uint32_t j = hits[k];
        const float r = std::sqrt(r2[j]);
        const float weight = 2.0f * rho0 / (rhoI + rhoJ[j]);
        const float pull = pullScale * cohesion(r) * (r > 0.0f ? 1.0f / r : 0.0f);
        ax -= weight * (pull * (q[0] - px[j]) + gamma * (n[0] - nx[j]));
        ay -= weight * (pull * (q[1] - py[j]) + gamma * (n[1] - ny[j]));
        az -= weight * (pull * (q[2] - pz[j]) + gamma * (n[2] - nz[j]));
      }
    }
    else
    {
#pragma omp simd reduction(+ : ax, ay, az)
      for (std::uint32_t k = 0; k < count; ++k)
      {
        const std::uint32_t j = hits[k];
        const float r = std::sqrt(r2[j]);
        const float pull = 2.0f * rho0 / (rhoI + rhoJ[j]) * pullScale * cohesion(r) * (r > 0.0f ? 1.0f / r : 0.0f);
        ax -= pull * (q[0] - px[j]);
        ay -= pull * (q[1] - py[j]);
        az -= pull * (q[2] - pz[j]);
      }
    }
    s.ax[i] += ax;
    s.ay[i] += ay;
    s.az[i] += az;
  };
  if (withCurvature)
  {
    forEachParticleByCell(this->Grid, s, h, threadCount(p), { s.density.data(), normal[0], normal[1], normal[2] },
                          pass);
  }
  else
  {
    forEachParticleByCell(this->Grid, s, h, threadCount(p), { s.density.data() }, pass);
  }
}
} // namespace parafluid::sph
