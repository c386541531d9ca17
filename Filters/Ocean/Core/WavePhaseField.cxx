#include "parafluid/ocean/WavePhaseField.h"

#include "parafluid/ocean/Bathymetry.h"
#include "parafluid/ocean/WaveDispersion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace parafluid::ocean
{
namespace
{
constexpr double kMaxSamples = 4.0e6;
}

WavePhaseField::WavePhaseField(const Bathymetry& bathymetry, double kDeep, const double direction[2],
                               const double bounds[4], double step, double minDepth)
{
  const double length = std::hypot(direction[0], direction[1]);
  if (!(length > 0.0) || !(kDeep > 0.0) || !(minDepth > 0.0))
  {
    throw std::invalid_argument("wave phase field: direction, wavenumber and minimum depth must be non-zero");
  }
  this->Direction[0] = direction[0] / length;
  this->Direction[1] = direction[1] / length;
  const double* d = this->Direction;
  // The region's corners in (s, t) = (along, across) coordinates.
  double s0 = 1e300, s1 = -1e300, t0 = 1e300, t1 = -1e300;
  for (int c = 0; c < 4; ++c)
  {
    const double x = bounds[c & 1], y = bounds[2 + (c >> 1)];
    const double s = d[0] * x + d[1] * y, t = -d[1] * x + d[0] * y;
    s0 = std::min(s0, s), s1 = std::max(s1, s), t0 = std::min(t0, t), t1 = std::max(t1, t);
  }
  step = std::max(step, 1e-6);
  while (((s1 - s0) / step + 2.0) * ((t1 - t0) / step + 2.0) > kMaxSamples)
  {
    step *= 1.25;
  }
  this->Step = step;
  this->S0 = s0;
  this->T0 = t0;
  this->NS = static_cast<int>(std::ceil((s1 - s0) / step)) + 1;
  this->NT = static_cast<int>(std::ceil((t1 - t0) / step)) + 1;
  const std::size_t n = static_cast<std::size_t>(this->NS) * this->NT;
  this->Phase.resize(n);
  this->Wavenumber.resize(n);
  this->PhaseAcross.resize(n);
  const int ns = this->NS, nt = this->NT;
#pragma omp parallel for schedule(static)
  for (int j = 0; j < nt; ++j)
  {
    const double t = t0 + j * step;
    double previous = 0.0, phase = 0.0;
    for (int i = 0; i < ns; ++i)
    {
      const double s = s0 + i * step;
      const double x = d[0] * s - d[1] * t, y = d[1] * s + d[0] * t;
      const double k = shoalingWavenumber(kDeep, std::max(bathymetry.depth(x, y), minDepth));
      // Trapezoid rule; the first sample makes uniform depth give exactly Phi = k s.
      phase = i == 0 ? k * s : phase + 0.5 * step * (previous + k);
      previous = k;
      const std::size_t index = static_cast<std::size_t>(j) * ns + i;
      this->Phase[index] = phase;
      this->Wavenumber[index] = static_cast<float>(k);
    }
  }
  for (int j = 0; j < nt; ++j)
  {
    const int below = std::max(j - 1, 0), above = std::min(j + 1, nt - 1);
    const double span = (above - below) * step;
    for (int i = 0; i < ns; ++i)
    {
      const double difference =
        this->Phase[static_cast<std::size_t>(above) * ns + i] - this->Phase[static_cast<std::size_t>(below) * ns + i];
      this->PhaseAcross[static_cast<std::size_t>(j) * ns + i] =
        span > 0.0 ? static_cast<float>(difference / span) : 0.0f;
    }
  }
}

void WavePhaseField::sample(double x, double y, double& phase, double& wavenumber, double gradient[2]) const
{
  const double* d = this->Direction;
  const double s = d[0] * x + d[1] * y, t = -d[1] * x + d[0] * y;
  const double gs = (s - this->S0) / this->Step, gt = (t - this->T0) / this->Step;
  const double cs = std::clamp(gs, 0.0, static_cast<double>(this->NS - 1));
  const double ct = std::clamp(gt, 0.0, static_cast<double>(this->NT - 1));
  const int i = std::min(static_cast<int>(cs), std::max(this->NS - 2, 0));
  const int j = std::min(static_cast<int>(ct), std::max(this->NT - 2, 0));
  const double fx = this->NS > 1 ? cs - i : 0.0, fy = this->NT > 1 ? ct - j : 0.0;
  const int i1 = std::min(i + 1, this->NS - 1), j1 = std::min(j + 1, this->NT - 1);
  auto at = [&](const auto& v)
  {
    const std::size_t r0 = static_cast<std::size_t>(j) * this->NS, r1 = static_cast<std::size_t>(j1) * this->NS;
    return (1 - fx) * (1 - fy) * v[r0 + i] + fx * (1 - fy) * v[r0 + i1] + (1 - fx) * fy * v[r1 + i] +
           fx * fy * v[r1 + i1];
  };
  wavenumber = at(this->Wavenumber);
  const double across = at(this->PhaseAcross);
  // Beyond the sampled region along the direction, continue with the edge's wavenumber.
  phase = at(this->Phase) + wavenumber * (gs - cs) * this->Step;
  gradient[0] = wavenumber * d[0] - across * d[1];
  gradient[1] = wavenumber * d[1] + across * d[0];
}
} // namespace parafluid::ocean
