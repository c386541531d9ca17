#include "parafluid/rain/DropTransfer.h"

#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace parafluid::rain
{
namespace
{
/// Unpolarised Fresnel reflectance at incidence i, refraction r.
double fresnel(double i, double r)
{
  if (i < 1e-9)
  {
    const double n = std::sin(r) > 0.0 ? std::sin(i) / std::sin(r) : 1.0;
    const double q = (n - 1.0) / (n + 1.0);
    return q * q;
  }
  const double rs = std::sin(i - r) / std::sin(i + r), rp = std::tan(i - r) / std::tan(i + r);
  return 0.5 * (rs * rs + rp * rp);
}
} // namespace

DropTransfer::DropTransfer(const DropTransferSettings& s)
  : Settings(s)
{
  if (!(s.refractiveIndex > 1.0 && s.refractiveIndex < 4.0) || s.interactions < 1 || s.interactions > 64 ||
      s.bins < 8 || s.bins > 100000 || s.samples < 100 || s.samples > 100000000 || !(s.absorption >= 0.0))
  {
    throw std::invalid_argument("DropTransfer: refractive index in (1, 4), 1-64 interactions, 8-100000 bins, "
                                "100-1e8 samples and a non-negative absorption are needed");
  }
  const int bins = s.bins;
  this->PathEnergy.assign(s.interactions, std::vector<double>(bins, 0.0));
  const double n = s.refractiveIndex;
  for (int k = 0; k < s.samples; ++k)
  {
    // Midpoints in beam area: b^2 uniform.
    const double b = std::sqrt((k + 0.5) / s.samples);
    const double i = std::asin(b), r = std::asin(b / n);
    const double reflect = fresnel(i, r), transmit = 1.0 - reflect;
    const double weight = 1.0 / s.samples;
    const double chord = 2.0 * std::cos(r); // in drop radii
    for (int p = 0; p < s.interactions; ++p)
    {
      double energy, deviation;
      if (p == 0)
      {
        energy = reflect;
        deviation = kPi - 2.0 * i;
      }
      else
      {
        energy = transmit * transmit * std::pow(reflect, p - 1) * std::exp(-s.absorption * chord * p);
        deviation = 2.0 * (i - r) + (p - 1) * (kPi - 2.0 * r);
      }
      const double theta = std::acos(std::cos(deviation)); // scattering angle in [0, pi]
      const int bin = std::min(bins - 1, static_cast<int>(theta / kPi * bins));
      this->PathEnergy[p][bin] += weight * energy;
    }
  }
  this->Phase.assign(bins, 0.0);
  for (int bin = 0; bin < bins; ++bin)
  {
    const double a0 = kPi * bin / bins, a1 = kPi * (bin + 1) / bins;
    const double solid = 2.0 * kPi * (std::cos(a0) - std::cos(a1));
    for (int p = 0; p < s.interactions; ++p)
    {
      this->Phase[bin] += this->PathEnergy[p][bin] / solid;
    }
  }
}

std::vector<double> DropTransfer::pathPhase(int p) const
{
  const int bins = this->Settings.bins;
  std::vector<double> phase(bins, 0.0);
  for (int bin = 0; bin < bins; ++bin)
  {
    const double a0 = kPi * bin / bins, a1 = kPi * (bin + 1) / bins;
    phase[bin] = this->PathEnergy.at(p)[bin] / (2.0 * kPi * (std::cos(a0) - std::cos(a1)));
  }
  return phase;
}

double DropTransfer::angle(int bin) const
{
  return kPi * (bin + 0.5) / this->Settings.bins;
}

double DropTransfer::energy() const
{
  double sum = 0.0;
  for (const auto& path : this->PathEnergy)
  {
    for (double e : path)
    {
      sum += e;
    }
  }
  return sum;
}

std::array<double, kSHBands> DropTransfer::zonal() const
{
  // lambda_l = 2 pi integral_{-1}^{1} P(t) P_l(t) dt, bin by bin with the Legendre polynomials'
  // antiderivatives (exact for a piecewise-constant P).
  const int bins = this->Settings.bins;
  auto antiderivative = [](int l, double t)
  {
    switch (l)
    {
      case 0:
        return t;
      case 1:
        return 0.5 * t * t;
      case 2:
        return 0.5 * (t * t * t - t);
      default:
        return (5.0 * t * t * t * t / 4.0 - 1.5 * t * t) / 2.0;
    }
  };
  std::array<double, kSHBands> lambda{};
  for (int bin = 0; bin < bins; ++bin)
  {
    const double t0 = std::cos(kPi * (bin + 1) / bins), t1 = std::cos(kPi * bin / bins);
    for (int l = 0; l < kSHBands; ++l)
    {
      lambda[l] += 2.0 * kPi * this->Phase[bin] * (antiderivative(l, t1) - antiderivative(l, t0));
    }
  }
  return lambda;
}

std::vector<float> DropTransfer::transferTable(int width, int height) const
{
  const auto lambda = this->zonal();
  std::vector<float> table(static_cast<std::size_t>(width) * height * kSHCount);
  for (int row = 0; row < height; ++row)
  {
    const double z = -1.0 + 2.0 * (row + 0.5) / height, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int col = 0; col < width; ++col)
    {
      const double phi = 2.0 * kPi * (col + 0.5) / width;
      const SHVector basis = shBasis(r * std::cos(phi), r * std::sin(phi), z);
      float* out = &table[(static_cast<std::size_t>(row) * width + col) * kSHCount];
      for (int l = 0; l < kSHBands; ++l)
      {
        for (int m = -l; m <= l; ++m)
        {
          out[shIndex(l, m)] = static_cast<float>(lambda[l] * basis[shIndex(l, m)]);
        }
      }
    }
  }
  return table;
}
} // namespace parafluid::rain
