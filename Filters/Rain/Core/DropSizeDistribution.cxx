#include "parafluid/rain/DropSizeDistribution.h"

#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace parafluid::rain
{
namespace
{
/// Integral over [kMinDiameter, kMaxDiameter] of f by Simpson's rule on 2000 intervals (the
/// integrands are smooth; 1e-10 relative).
template<class F>
double integrate(F f)
{
  const int n = 2000;
  const double a = DropSizeDistribution::kMinDiameter, b = DropSizeDistribution::kMaxDiameter, h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int k = 1; k < n; ++k)
  {
    sum += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  }
  return sum * h / 3.0;
}
} // namespace

DropSizeDistribution::DropSizeDistribution(double rainfallRate)
{
  if (!(rainfallRate > 0.0) || !std::isfinite(rainfallRate) || rainfallRate > 1e4)
  {
    throw std::invalid_argument("RainfallRate must be between 0 and 10000 mm/h (got " + std::to_string(rainfallRate) +
                                ")");
  }
  this->Rate = rainfallRate / 3.6e6;
  this->Lambda = 4.1e3 * std::pow(rainfallRate, -0.21); // 4.1 R^-0.21 per mm, in 1/m
  const double lambda = this->Lambda;
  const double flux = integrate([lambda](double d) { return std::exp(-lambda * d) * terminalSpeed(d) * volume(d); });
  this->N0 = this->Rate / flux;
  this->DropsPerVolume = this->N0 / lambda * (std::exp(-lambda * kMinDiameter) - std::exp(-lambda * kMaxDiameter));
  const double n0 = this->N0;
  this->NumberFlux = integrate([n0, lambda](double d) { return n0 * std::exp(-lambda * d) * terminalSpeed(d); });
}

double DropSizeDistribution::density(double diameter) const
{
  return this->N0 * std::exp(-this->Lambda * diameter);
}

double DropSizeDistribution::cumulative(double diameter) const
{
  const double d = std::clamp(diameter, kMinDiameter, kMaxDiameter);
  const double lo = std::exp(-this->Lambda * kMinDiameter), hi = std::exp(-this->Lambda * kMaxDiameter);
  return (lo - std::exp(-this->Lambda * d)) / (lo - hi);
}

double DropSizeDistribution::diameterAt(double u) const
{
  const double lo = std::exp(-this->Lambda * kMinDiameter), hi = std::exp(-this->Lambda * kMaxDiameter);
  const double d = -std::log(lo - std::clamp(u, 0.0, 1.0) * (lo - hi)) / this->Lambda;
  return std::clamp(d, kMinDiameter, kMaxDiameter);
}

double DropSizeDistribution::terminalSpeed(double diameter)
{
  const double mm = diameter * 1e3;
  return std::max(9.65 - 10.3 * std::exp(-0.6 * mm), 0.1);
}

double DropSizeDistribution::volume(double diameter)
{
  return kPi / 6.0 * diameter * diameter * diameter;
}
} // namespace parafluid::rain
