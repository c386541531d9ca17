#include "parafluid/ocean/GerstnerOcean.h"
#include "parafluid/common/MathConstants.h"

#include "parafluid/ocean/Bathymetry.h"

#include <algorithm>
#include <cmath>
#include <omp.h>
#include <stdexcept>
#include <string>

namespace parafluid::ocean
{
namespace
{

double smoothstep(double lo, double hi, double v)
{
  const double t = std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// Per-wave quantities at one point, between the two passes of evaluate().
struct WaveAtPoint
{
  double sinTheta, cosTheta, cosTheta0, gradient[2], direction[2], k, sx, sz, decay;
};

/// sin and cos of theta0 - delta from those of theta0, for the wind's phase shift delta in
/// [0, 0.5]: Taylor series to delta^7 and delta^8 (errors under 1e-8), so a wave costs one sine
/// and one cosine, on the CPU and in the shader alike.
void shiftPhase(float s0, float c0, float delta, float& s, float& c)
{
  const float d2 = delta * delta;
  const float sd = delta * (1.0f - d2 / 6.0f * (1.0f - d2 / 20.0f * (1.0f - d2 / 42.0f)));
  const float cd = 1.0f - d2 / 2.0f * (1.0f - d2 / 12.0f * (1.0f - d2 / 30.0f * (1.0f - d2 / 56.0f)));
  s = s0 * cd - c0 * sd;
  c = c0 * cd + s0 * sd;
}
} // namespace

void displacementBound(const OceanParameters& p, bool overFloor, double& horizontal, double& vertical)
{
  horizontal = vertical = 0.0;
  for (const GerstnerWave& w : p.waves)
  {
    vertical += w.amplitude * (1.0 + p.breakingStretch);
    horizontal += w.amplitude * (w.steepness + p.breakingShift);
    if (overFloor)
    {
      horizontal += p.maxSteepness * w.wavelength / (2.0 * kPi);
    }
  }
}

void validate(const OceanParameters& p)
{
  validateWaves(p.waves);
  if (p.waves.size() > static_cast<std::size_t>(GerstnerOcean::kMaxWaves))
  {
    throw std::invalid_argument("ocean: at most " + std::to_string(GerstnerOcean::kMaxWaves) + " waves");
  }
  if (!(p.gravity > 0.0) || !std::isfinite(p.gravity))
  {
    throw std::invalid_argument("ocean: gravity must be positive");
  }
  if (!(p.depth > 0.0))
  {
    throw std::invalid_argument("ocean: water depth must be positive (infinite for deep water)");
  }
  if (!(p.maxSteepness > 0.0 && p.maxSteepness <= 1.0))
  {
    throw std::invalid_argument("ocean: MaxSteepness must lie in (0, 1]; 1 is where the surface folds");
  }
  if (!(p.windLean >= 0.0 && p.windLean <= 0.5))
  {
    throw std::invalid_argument("ocean: WindLean must lie in [0, 0.5]");
  }
  if (!(p.breakingDepthRatio > 0.0) || !(p.minDepth > 0.0) || !(p.breakingStretch >= 0.0) ||
      !(p.breakingLean >= 0.0 && p.breakingLean < 1.5) || !(p.breakingShift >= 0.0) || !std::isfinite(p.windDirection))
  {
    throw std::invalid_argument("ocean: breaking parameters and minimum depth must be positive (lean below 1.5 rad)");
  }
}

GerstnerOcean::GerstnerOcean(OceanParameters parameters, std::shared_ptr<const Bathymetry> bathymetry,
                             const double region[4])
  : Parameters(std::move(parameters))
  , Floor(std::move(bathymetry))
  , Waves(this->Parameters.waves)
{
  validate(this->Parameters);
  const OceanParameters& p = this->Parameters;
  const double wind[2] = { std::cos(p.windDirection * kPi / 180.0), std::sin(p.windDirection * kPi / 180.0) };
  double total = 0.0;
  for (const GerstnerWave& w : this->Waves)
  {
    const double k = w.deepWavenumber();
    const double d[2] = { std::cos(w.direction * kPi / 180.0), std::sin(w.direction * kPi / 180.0) };
    this->DeepK.push_back(k);
    this->Omega.push_back(std::sqrt(p.gravity * k));
    this->DirX.push_back(d[0]);
    this->DirY.push_back(d[1]);
    this->Lean.push_back(p.windLean * std::max(d[0] * wind[0] + d[1] * wind[1], 0.0));
    // Uniform finite depth: the wave is shorter than in deep water, at the same frequency.
    const double local = (this->Floor || std::isinf(p.depth)) ? k : shoalingWavenumber(k, p.depth);
    this->UniformK.push_back(local);
    // |d theta / dx| reaches k (1 + lean / 2) where the wind term is steepest.
    total += w.steepness * local * w.amplitude * (1.0 + 0.5 * this->Lean.back());
  }
  if (total > p.maxSteepness)
  {
    for (GerstnerWave& w : this->Waves)
    {
      w.steepness *= p.maxSteepness / total;
    }
  }
  if (this->Floor)
  {
    double covered[4];
    if (region)
    {
      std::copy(region, region + 4, covered);
    }
    else
    {
      this->Floor->bounds(covered);
    }
    const double extent = std::max(covered[1] - covered[0], covered[3] - covered[2]);
    const double step = std::max(std::min(this->Floor->spacing(), extent / 256.0), extent / 2048.0);
    for (std::size_t i = 0; i < this->Waves.size(); ++i)
    {
      const double d[2] = { this->DirX[i], this->DirY[i] };
      this->Phases.emplace_back(*this->Floor, this->DeepK[i], d, covered, step, p.minDepth);
    }
  }
}

void GerstnerOcean::evaluate(const float* xs, const float* ys, std::size_t n, double time, float* displacement,
                             float* normal, float* jacobian, float* foam, float* depthOut, int threads) const
{
  const OceanParameters& p = this->Parameters;
  const int waves = static_cast<int>(this->Waves.size());
  const int useThreads = threads > 0 ? threads : omp_get_max_threads();
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) num_threads(useThreads)
  for (std::int64_t index = 0; index < count; ++index)
  {
    const double x = xs[index], y = ys[index];
    const double h = this->Floor ? this->Floor->depth(x, y) : p.depth;
    double slope[2] = { 0.0, 0.0 };
    if (this->Floor)
    {
      this->Floor->depthGradient(x, y, slope);
    }
    double offset[3] = { 0.0, 0.0, 0.0 };
    // d(displacement)/dx and /dy.
    double dx[3] = { 0.0, 0.0, 0.0 }, dy[3] = { 0.0, 0.0, 0.0 };
    double breakingCrest = 0.0;
    if (h > p.minDepth)
    {
      WaveAtPoint at[kMaxWaves];
      double horizontalSteepness = 0.0;
      for (int i = 0; i < waves; ++i)
      {
        const GerstnerWave& w = this->Waves[i];
        WaveAtPoint& a = at[i];
        double phi;
        if (this->Floor)
        {
          this->Phases[i].sample(x, y, phi, a.k, a.gradient);
        }
        else
        {
          a.k = this->UniformK[i];
          a.gradient[0] = a.k * this->DirX[i];
          a.gradient[1] = a.k * this->DirY[i];
          phi = a.gradient[0] * x + a.gradient[1] * y;
        }
        const double g = std::sqrt(a.gradient[0] * a.gradient[0] + a.gradient[1] * a.gradient[1]);
        a.direction[0] = g > 0.0 ? a.gradient[0] / g : this->DirX[i];
        a.direction[1] = g > 0.0 ? a.gradient[1] / g : this->DirY[i];
        // Reduced to [-pi, pi] in double, then single-precision trigonometry (what the GPU does):
        // twice as fast, and the phase error stays under 1e-6 rad.
        const double unreduced = phi - this->Omega[i] * time + w.phase;
        const auto theta0 = static_cast<float>(unreduced - 2.0 * kPi * std::nearbyint(unreduced * (0.5 / kPi)));
        const float s0 = std::sin(theta0), c0 = std::cos(theta0);
        a.cosTheta0 = c0;
        float s, c;
        shiftPhase(s0, c0, static_cast<float>(0.5 * this->Lean[i] * (1.0 + s0)), s, c);
        a.sinTheta = s;
        a.cosTheta = c;
        a.decay = std::isinf(h) ? 0.0 : std::exp(-a.k * h);
        a.sx = 1.0 / (1.0 - a.decay);
        a.sz = 1.0 - a.decay;
        horizontalSteepness += w.steepness * w.amplitude * a.sx * g * (1.0 + 0.5 * this->Lean[i]);
      }
      // Near the shore the major axes grow; limit them before orbits loop.
      const double limit = horizontalSteepness > p.maxSteepness ? p.maxSteepness / horizontalSteepness : 1.0;
      for (int i = 0; i < waves; ++i)
      {
        const GerstnerWave& w = this->Waves[i];
        const WaveAtPoint& a = at[i];
        const double A = w.amplitude, sx = a.sx * limit, sz = a.sz;
        const double S = a.sinTheta, C = a.cosTheta;
        const double P = std::max(S, 0.0), dP = S > 0.0 ? C : 0.0;
        // Breaking weight from the local height against the depth: zero in deep water.
        const double b =
          std::isinf(h) ? 0.0 : smoothstep(0.7 * p.breakingDepthRatio, p.breakingDepthRatio, 2.0 * A * sz / h);
        breakingCrest = std::max(breakingCrest, b * P);
        const double ahead = -(slope[0] * a.direction[0] + slope[1] * a.direction[1]);
        const double alpha = (ahead > 0.0 && a.decay > 0.0 ? std::atan(ahead) * a.decay : 0.0) + b * p.breakingLean * P;
        const double dAlpha = b * p.breakingLean * dP;
        const double u = w.steepness * A * sx * C + b * p.breakingShift * A * P * P;
        const double du = -w.steepness * A * sx * S + b * p.breakingShift * A * 2.0 * P * dP;
        const double v = A * sz * S + b * p.breakingStretch * A * sz * P * P;
        const double dv = A * sz * C + b * p.breakingStretch * A * sz * 2.0 * P * dP;
        // Untilted orbits (all of deep water) skip the rotation's trigonometry.
        const double ca = alpha != 0.0 ? std::cos(alpha) : 1.0, sa = alpha != 0.0 ? std::sin(alpha) : 0.0;
        const double along = u * ca + v * sa;
        const double up = v * ca - u * sa;
        const double dAlong = du * ca + dv * sa + (-u * sa + v * ca) * dAlpha;
        const double dUp = dv * ca - du * sa + (-v * sa - u * ca) * dAlpha;
        offset[0] += a.direction[0] * along;
        offset[1] += a.direction[1] * along;
        offset[2] += up;
        // d theta / d(x, y) = (1 - lean cos theta0 / 2) grad Phi.
        const double chain = 1.0 - 0.5 * this->Lean[i] * a.cosTheta0;
        const double gx = chain * a.gradient[0], gy = chain * a.gradient[1];
        dx[0] += a.direction[0] * dAlong * gx;
        dx[1] += a.direction[1] * dAlong * gx;
        dx[2] += dUp * gx;
        dy[0] += a.direction[0] * dAlong * gy;
        dy[1] += a.direction[1] * dAlong * gy;
        dy[2] += dUp * gy;
      }
    }
    const double tx[3] = { 1.0 + dx[0], dx[1], dx[2] }, ty[3] = { dy[0], 1.0 + dy[1], dy[2] };
    const double J = tx[0] * ty[1] - tx[1] * ty[0];
    if (displacement)
    {
      for (int c = 0; c < 3; ++c)
      {
        displacement[3 * index + c] = static_cast<float>(offset[c]);
      }
    }
    if (normal)
    {
      double nv[3] = { tx[1] * ty[2] - tx[2] * ty[1], tx[2] * ty[0] - tx[0] * ty[2], J };
      const double length = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
      for (int c = 0; c < 3; ++c)
      {
        normal[3 * index + c] = static_cast<float>(length > 0.0 ? nv[c] / length : (c == 2 ? 1.0 : 0.0));
      }
    }
    if (jacobian)
    {
      jacobian[index] = static_cast<float>(J);
    }
    if (foam)
    {
      // Whitecaps where the surface is squeezed to under 60 % of its area, and breaking crests.
      foam[index] = static_cast<float>(std::clamp(std::max(breakingCrest, (0.6 - J) / 0.6), 0.0, 1.0));
    }
    if (depthOut)
    {
      depthOut[index] = static_cast<float>(std::isinf(h) ? 1e30 : std::max(h, 0.0));
    }
  }
}
} // namespace parafluid::ocean
