#pragma once
// The particle-surface scenes of issue 6, shared by the surface benchmark and the OpenVDB peer
// program so that both measure the same particles.
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace parafluid::benchmarks
{
// n particles in all: 95 % on the lattice of a dam-break block (a x a x 2a), 5 % scattered in a
// slab as high again above it. Returns the positions; d receives the lattice spacing
// (1M particles: d = 0.0064 m, a = 0.51 m, as in the issue).
inline std::vector<float> damBreakWithSplash(std::size_t n, double& d)
{
  const std::size_t inBlock = static_cast<std::size_t>(0.95 * n);
  const int side = static_cast<int>(std::lround(std::cbrt(inBlock / 2.0)));
  d = 0.0064 * 100.0 / side;
  const double a = side * d;
  std::vector<float> xyz;
  xyz.reserve(3 * n);
  for (int k = 0; k < 2 * side; ++k)
  {
    for (int j = 0; j < side; ++j)
    {
      for (int i = 0; i < side; ++i)
      {
        xyz.insert(xyz.end(), { float((i + 0.5) * d), float((j + 0.5) * d), float((k + 0.5) * d) });
      }
    }
  }
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  while (xyz.size() < 3 * n)
  {
    xyz.insert(xyz.end(), { float(u(rng) * 2 * a), float(u(rng) * a), float(2 * a + u(rng) * 2 * a) });
  }
  return xyz;
}

// The accuracy scene: lattice points of spacing d within radius R = 25 d of the origin, each
// moved by a uniform jitter of up to 0.1 d per axis.
inline std::vector<float> jitteredBall(double d, double radius)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1 * d, 0.1 * d);
  const int n = static_cast<int>(std::ceil(radius / d)) + 1;
  std::vector<float> xyz;
  for (int k = -n; k <= n; ++k)
  {
    for (int j = -n; j <= n; ++j)
    {
      for (int i = -n; i <= n; ++i)
      {
        if ((i * i + j * j + k * k) * d * d <= radius * radius)
        {
          xyz.insert(xyz.end(), { float(i * d + u(rng)), float(j * d + u(rng)), float(k * d + u(rng)) });
        }
      }
    }
  }
  return xyz;
}

// Mean |r - R| of points (x, y, z triples) about the origin.
inline double meanRadialError(const float* points, std::size_t count, double radius)
{
  double sum = 0.0;
  for (std::size_t v = 0; v < count; ++v)
  {
    const double x = points[3 * v], y = points[3 * v + 1], z = points[3 * v + 2];
    sum += std::abs(std::sqrt(x * x + y * y + z * z) - radius);
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}
} // namespace parafluid::benchmarks
