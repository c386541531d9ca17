// The pressure SPH Step outputs: each particle's neighbourhood fitted with a linear field by weighted
// least squares, read at the particle (first-order moving least squares: Lancaster & Salkauskas
// 1981; in SPH, Dilts 1999 and Colagrossi & Landrini 2003). On a full neighbourhood it is the
// Shepard mean (the odd moments vanish); where a free surface cuts the neighbourhood a linear field
// still comes out exact, where the Shepard mean (the output until 2026-11-29) read the neighbours'
// centroid instead of the particle: half a spacing or more inside the fluid, so a resting
// column's top layer read twice its hydrostatic pressure. Box walls are filled by mirror images
// whose pressure is lifted hydrostatically, as δ-SPH's forces do; evenly reflected, they had
// forced a zero gradient across the floor and the floor layer read low.
#include "parafluid/sph/SPHSolver.h"

#include "private/NeighbourCandidates.h"
#include "private/OutputFields.h"
#include "private/WallImages.h"

#include "parafluid/common/SimdDispatch.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace parafluid::sph
{
namespace
{
// Added to the neighbours' spread (their weighted covariance, in units of the support radius
// squared; a full neighbourhood's is about 0.09 along each axis) before it is inverted, so that a
// flat sheet one particle thick, with no spread across it, gets no gradient across it (the Shepard
// mean in that direction) instead of a division by zero. Small enough that it biases the fitted
// gradient elsewhere by under 1e-4 of itself (1e-3 left 1 Pa at a 0.12 m column's surface).
constexpr double kSpreadFloor = 1e-6;

/// p_i + the intercept of the least-squares linear fit of (p_j - p_i) over offsets x_j - x_i (in
/// units of the support radius) with weights w_j, given the sums over j of w, w x, w x x^T (xx,
/// xy, xz, yy, yz, zz), w (p_j - p_i) and w (p_j - p_i) x.
float linearFitAtParticle(float pressure, const double s0, const double s1[3], const double s2[6], double p0,
                          const double p1[3])
{
  if (!(s0 > 0.0))
  {
    return pressure;
  }
  const Eigen::Vector3d centroid(s1[0] / s0, s1[1] / s0, s1[2] / s0);
  Eigen::Matrix3d spread;
  spread << s2[0], s2[1], s2[2], s2[1], s2[3], s2[4], s2[2], s2[4], s2[5];
  spread = spread / s0 - centroid * centroid.transpose();
  spread.diagonal().array() += kSpreadFloor;
  const double mean = p0 / s0;
  const Eigen::Vector3d covariance = Eigen::Vector3d(p1[0], p1[1], p1[2]) / s0 - centroid * mean;
  // The spread is symmetric and, with its floor, positive definite: a Cholesky solve.
  const Eigen::Vector3d gradient = spread.llt().solve(covariance);
  const double fitted = pressure + mean - centroid.dot(gradient);
  return std::isfinite(fitted) ? static_cast<float>(fitted) : pressure;
}

/// One query's neighbours for the fit: the candidate buffer's arrays (positions, volume m / rho,
/// pressure, density) as raw pointers and the padded hits, the query q, its mirror's scale over
/// the support radius, and the hydrostatic lift of its images' pressures (see smoothedPressure).
struct FitInput
{
  const float *px, *py, *pz, *volume, *pressure, *rho;
  const std::uint32_t* hits;
  std::uint32_t count;
  float q[3], scaleOverH[3], lift[4], h2, pi;
};

/// The 14 sums of the fit over the hits (see linearFitAtParticle): w, w u (3), w u u^T (6), w f,
/// w f u (3), with u the offset over the support radius and f the lifted pressure less p_i. The
/// padding's far sentinel adds exactly zero (its weight is zero and its other factors finite).
__attribute__((always_inline)) inline void fitSumsBody(const FitInput& in, float* out)
{
  const float *px = in.px, *py = in.py, *pz = in.pz, *v = in.volume, *pj = in.pressure, *rho = in.rho;
  const std::uint32_t* hits = in.hits;
  const float sx = in.scaleOverH[0], sy = in.scaleOverH[1], sz = in.scaleOverH[2];
  float w0 = 0.0f, wx = 0.0f, wy = 0.0f, wz = 0.0f, wxx = 0.0f, wxy = 0.0f, wxz = 0.0f, wyy = 0.0f, wyz = 0.0f,
        wzz = 0.0f, f0 = 0.0f, fx = 0.0f, fy = 0.0f, fz = 0.0f;
#pragma omp simd reduction(+ : w0, wx, wy, wz, wxx, wxy, wxz, wyy, wyz, wzz, f0, fx, fy, fz)
  for (std::uint32_t n = 0; n < in.count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = px[j] - in.q[0], dy = py[j] - in.q[1], dz = pz[j] - in.q[2];
    const float e = in.h2 - (dx * dx + dy * dy + dz * dz);
    const float d = e > 0.0f ? e : 0.0f;
    const float w = v[j] * d * d * d; // poly6 without its constant, which cancels
    const float ux = sx * dx, uy = sy * dy, uz = sz * dz;
    const float value = pj[j] + rho[j] * (in.lift[0] * px[j] + in.lift[1] * py[j] + in.lift[2] * pz[j] + in.lift[3]);
    const float f = w * (value - in.pi);
    w0 += w;
    wx += w * ux;
    wy += w * uy;
    wz += w * uz;
    wxx += w * ux * ux;
    wxy += w * ux * uy;
    wxz += w * ux * uz;
    wyy += w * uy * uy;
    wyz += w * uy * uz;
    wzz += w * uz * uz;
    f0 += f;
    fx += f * ux;
    fy += f * uy;
    fz += f * uz;
  }
  out[0] = w0;
  out[1] = wx;
  out[2] = wy;
  out[3] = wz;
  out[4] = wxx;
  out[5] = wxy;
  out[6] = wxz;
  out[7] = wyy;
  out[8] = wyz;
  out[9] = wzz;
  out[10] = f0;
  out[11] = fx;
  out[12] = fy;
  out[13] = fz;
}

// Compiled for AVX-512, AVX2 and the baseline (parafluid/common/SimdDispatch.h).
PARAFLUID_SIMD_DISPATCH(fitSums, (const FitInput& in, float* out), (in, out), fitSumsBody)
} // namespace

std::vector<float> SPHSolver::smoothedPressure() const
{
  return detail::smoothedPressureOnGrid(this->Grid, this->State, this->Parameters);
}

std::vector<float> detail::smoothedPressureOnGrid(const NeighbourGrid& grid, const ParticleState& s,
                                                  const SPHParameters& p)
{
  std::vector<float> volume(s.size()), smoothed(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    volume[i] = p.particleMass / s.density[i];
  }
  const float h2 = p.smoothingLength * p.smoothingLength;
  const float inverseH = 1.0f / p.smoothingLength;
  const float* g = p.gravity.data();
  detail::forEachParticleByCell(
    grid, s, p.smoothingLength, detail::threadCount(p), { volume.data(), s.pressure.data(), s.density.data() },
    [&](detail::CandidateBuffer& c, std::uint32_t i)
    {
      const float x[3] = { s.x[i], s.y[i], s.z[i] };
      const float pi = s.pressure[i];
      double sums[14] = {}; // w, w u (3), w u u^T (6), w f, w f u (3), over the particle and its images
      // The query q (the particle, or its image across box walls: R x_i, R x = s x + o) against
      // each candidate j is particle i against R x_j, at offset s (x_j - q) from x_i. An image
      // carries its particle's pressure lifted hydrostatically to where it lies, p_j + rho_j g .
      // (R x_j - x_j) (Adami, Hu & Adams 2012, a wall at rest): a field with a gradient across the
      // wall, any fluid under gravity on a floor, continues across it instead of being reflected
      // (an even reflection forces a zero gradient at the wall: the floor layer read low).
      auto accumulate = [&](const float* q, const float* scale, bool image)
      {
        FitInput in;
        in.px = c.x.data();
        in.py = c.y.data();
        in.pz = c.z.data();
        in.volume = c.channel[0].data();
        in.pressure = c.channel[1].data();
        in.rho = c.channel[2].data();
        // Only the candidates inside the support (about 15 % of them; an image's among its
        // particle's, found first), padded to whole vectors.
        in.hits = image ? c.imageHits.data() : c.hits.data();
        in.count = image ? c.findImageHits(q, h2) : c.padHits(c.findHits(q, h2, false));
        detail::hydrostaticImageLift(q, x, scale, g, in.lift); // rho_j (lift . x_j + lift[3])
        for (int a = 0; a < 3; ++a)
        {
          in.q[a] = q[a];
          in.scaleOverH[a] = scale[a] * inverseH;
        }
        in.h2 = h2;
        in.pi = pi;
        float part[14];
        fitSums(in, part);
        for (int k = 0; k < 14; ++k)
        {
          sums[k] += part[k];
        }
      };
      // (The velocity slot is unused: the pressure sees no velocity.)
      detail::forEachWallImage(x, x, p,
                               [&](const float* q, const float*, const float*, const float* scale, bool image)
                               { accumulate(q, scale, image); });
      smoothed[i] = linearFitAtParticle(pi, sums[0], sums + 1, sums + 4, sums[10], sums + 11);
    });
  return smoothed;
}
} // namespace parafluid::sph
