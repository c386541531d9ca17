#include "parafluid/rain/SphericalHarmonics.h"

#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace parafluid::rain
{
SHVector shBasis(double x, double y, double z)
{
  // Normalisation constants of the real harmonics (e.g. Sloan, "Stupid Spherical Harmonics
  // Tricks", 2008), written out in Cartesian form.
  const double c0 = 0.5 * std::sqrt(1.0 / kPi);
  const double c1 = std::sqrt(3.0 / (4.0 * kPi));
  const double c2a = 0.5 * std::sqrt(15.0 / kPi), c2b = 0.25 * std::sqrt(5.0 / kPi), c2c = 0.25 * std::sqrt(15.0 / kPi);
  const double c3a = 0.25 * std::sqrt(35.0 / (2.0 * kPi)), c3b = 0.5 * std::sqrt(105.0 / kPi),
               c3c = 0.25 * std::sqrt(21.0 / (2.0 * kPi)), c3d = 0.25 * std::sqrt(7.0 / kPi),
               c3e = 0.25 * std::sqrt(105.0 / kPi);
  SHVector y_{};
  y_[shIndex(0, 0)] = c0;
  y_[shIndex(1, -1)] = c1 * y;
  y_[shIndex(1, 0)] = c1 * z;
  y_[shIndex(1, 1)] = c1 * x;
  y_[shIndex(2, -2)] = c2a * x * y;
  y_[shIndex(2, -1)] = c2a * y * z;
  y_[shIndex(2, 0)] = c2b * (3.0 * z * z - 1.0);
  y_[shIndex(2, 1)] = c2a * x * z;
  y_[shIndex(2, 2)] = c2c * (x * x - y * y);
  y_[shIndex(3, -3)] = c3a * y * (3.0 * x * x - y * y);
  y_[shIndex(3, -2)] = c3b * x * y * z;
  y_[shIndex(3, -1)] = c3c * y * (5.0 * z * z - 1.0);
  y_[shIndex(3, 0)] = c3d * z * (5.0 * z * z - 3.0);
  y_[shIndex(3, 1)] = c3c * x * (5.0 * z * z - 1.0);
  y_[shIndex(3, 2)] = c3e * z * (x * x - y * y);
  y_[shIndex(3, 3)] = c3a * x * (x * x - 3.0 * y * y);
  return y_;
}

namespace
{
/// Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre recurrence).
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights)
{
  nodes.resize(n);
  weights.resize(n);
  for (int i = 0; i < n; ++i)
  {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration)
    {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k)
      {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::fabs(step) < 1e-15)
      {
        break;
      }
    }
    nodes[i] = x;
    weights[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}
} // namespace

SHVector shProject(const std::function<double(double, double, double)>& f, int rings)
{
  std::vector<double> nodes, weights;
  gaussLegendre(rings, nodes, weights);
  const int sectors = 2 * rings;
  SHVector sum{};
  for (int i = 0; i < rings; ++i)
  {
    const double z = nodes[i], r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < sectors; ++j)
    {
      const double phi = 2.0 * kPi * j / sectors;
      const double x = r * std::cos(phi), y = r * std::sin(phi);
      const double w = weights[i] * 2.0 * kPi / sectors * f(x, y, z);
      const SHVector basis = shBasis(x, y, z);
      for (int k = 0; k < kSHCount; ++k)
      {
        sum[k] += w * basis[k];
      }
    }
  }
  return sum;
}

double shEvaluate(const SHVector& c, double x, double y, double z)
{
  const SHVector basis = shBasis(x, y, z);
  double sum = 0.0;
  for (int k = 0; k < kSHCount; ++k)
  {
    sum += c[k] * basis[k];
  }
  return sum;
}

std::vector<double> shProjectCubeMap(const std::array<const float*, 6>& faces, int size, int channels)
{
  std::vector<double> sum(static_cast<std::size_t>(channels) * kSHCount, 0.0);
  // Solid angle of the texel [u0, u1] x [v0, v1] on a face at distance 1: the difference of the
  // area element's antiderivative atan(u v / sqrt(u^2 + v^2 + 1)) at the corners.
  auto area = [](double u, double v) { return std::atan2(u * v, std::sqrt(u * u + v * v + 1.0)); };
  for (int face = 0; face < 6; ++face)
  {
    for (int row = 0; row < size; ++row)
    {
      for (int col = 0; col < size; ++col)
      {
        const double u0 = 2.0 * col / size - 1.0, u1 = 2.0 * (col + 1) / size - 1.0;
        const double v0 = 2.0 * row / size - 1.0, v1 = 2.0 * (row + 1) / size - 1.0;
        const double weight = area(u1, v1) - area(u0, v1) - area(u1, v0) + area(u0, v0);
        const double sc = 0.5 * (u0 + u1), tc = 0.5 * (v0 + v1); // rows run down: t grows with row
        // OpenGL's cube-map face table (major axis, s and t directions).
        double d[3];
        switch (face)
        {
          case 0:
            d[0] = 1, d[1] = -tc, d[2] = -sc;
            break;
          case 1:
            d[0] = -1, d[1] = -tc, d[2] = sc;
            break;
          case 2:
            d[0] = sc, d[1] = 1, d[2] = tc;
            break;
          case 3:
            d[0] = sc, d[1] = -1, d[2] = -tc;
            break;
          case 4:
            d[0] = sc, d[1] = -tc, d[2] = 1;
            break;
          default:
            d[0] = -sc, d[1] = -tc, d[2] = -1;
            break;
        }
        const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const SHVector basis = shBasis(d[0] / norm, d[1] / norm, d[2] / norm);
        const float* texel = faces[face] + (static_cast<std::size_t>(row) * size + col) * channels;
        for (int c = 0; c < channels; ++c)
        {
          for (int k = 0; k < kSHCount; ++k)
          {
            sum[static_cast<std::size_t>(c) * kSHCount + k] += weight * texel[c] * basis[k];
          }
        }
      }
    }
  }
  return sum;
}
} // namespace parafluid::rain
