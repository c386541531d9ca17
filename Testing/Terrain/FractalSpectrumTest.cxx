// The fractal sums have the spectra their parameters imply: along a line, a fractional Brownian
// surface of Hurst exponent H has power ~ k^(-2H-1). For fBm, H = -log(persistence) /
// log(lacunarity); for diamond-square, H is its roughness. Measured on 1024^2 fields: the mean
// periodogram of the Hann-windowed rows, its log-log slope fitted over the band the octaves (or
// levels) cover, away from both ends.
#include "parafluid/terrain/DiamondSquare.h"
#include "parafluid/terrain/TerrainGenerator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

namespace
{
using namespace parafluid::terrain;

/// In-place radix-2 FFT (n a power of two).
void fft(std::vector<std::complex<double>>& a)
{
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i)
  {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1)
    {
      j ^= bit;
    }
    j ^= bit;
    if (i < j)
    {
      std::swap(a[i], a[j]);
    }
  }
  for (std::size_t len = 2; len <= n; len <<= 1)
  {
    const double angle = -2.0 * M_PI / static_cast<double>(len);
    const std::complex<double> w(std::cos(angle), std::sin(angle));
    for (std::size_t i = 0; i < n; i += len)
    {
      std::complex<double> wk(1.0, 0.0);
      for (std::size_t k = 0; k < len / 2; ++k, wk *= w)
      {
        const std::complex<double> u = a[i + k], v = a[i + k + len / 2] * wk;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
      }
    }
  }
}

/// Least-squares slope of log(power) against log(frequency) for frequencies [lo, hi] cycles per
/// sample, from the mean periodogram of the rows of an n x n field (n a power of two).
double spectralSlope(const std::vector<float>& field, int n, int stride, double lo, double hi)
{
  std::vector<double> power(static_cast<std::size_t>(n / 2), 0.0);
  std::vector<std::complex<double>> row(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j)
  {
    double mean = 0.0;
    for (int i = 0; i < n; ++i)
    {
      mean += field[static_cast<std::size_t>(j) * stride + i];
    }
    mean /= n;
    for (int i = 0; i < n; ++i)
    {
      const double hann = 0.5 - 0.5 * std::cos(2.0 * M_PI * i / (n - 1));
      row[static_cast<std::size_t>(i)] = hann * (field[static_cast<std::size_t>(j) * stride + i] - mean);
    }
    fft(row);
    for (int k = 1; k < n / 2; ++k)
    {
      power[static_cast<std::size_t>(k)] += std::norm(row[static_cast<std::size_t>(k)]);
    }
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (int k = 1; k < n / 2; ++k)
  {
    const double f = static_cast<double>(k) / n;
    if (f < lo || f > hi)
    {
      continue;
    }
    const double x = std::log(f), y = std::log(power[static_cast<std::size_t>(k)]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
  }
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

std::vector<float> fbmField(float persistence, int n)
{
  TerrainSettings s;
  s.seed = 42;
  s.fractal.octaves = 8;
  s.fractal.lacunarity = 2.0f;
  s.fractal.persistence = persistence;
  s.featureSize = 1024.0; // first octave: one wavelength across the field; the 8th: 8 samples
  s.heightScale = 1.0;
  ElevationGrid grid;
  grid.nx = grid.ny = n;
  grid.dx = grid.dy = 1.0;
  generateTerrain(s, grid);
  return grid.elevation;
}

TEST(FractalSpectrum, FBmSlopeFollowsPersistenceAndLacunarity)
{
  const int n = 1024;
  for (const float persistence : { 0.5f, 0.7071068f })
  {
    const double hurst = -std::log(persistence) / std::log(2.0);
    const double expected = -2.0 * hurst - 1.0;
    // The octaves cover 1/1024 .. 1/8 cycles per sample; fit one octave inside either end.
    const double slope = spectralSlope(fbmField(persistence, n), n, n, 1.0 / 512, 1.0 / 16);
    std::printf("fBm persistence %.4f: spectral slope %.3f, expected %.3f\n", persistence, slope, expected);
    EXPECT_NEAR(slope, expected, 0.1 * std::fabs(expected)) << "persistence " << persistence;
  }
}

TEST(FractalSpectrum, DiamondSquareSlopeFollowsRoughness)
{
  const int levels = 10, size = 1025, n = 1024;
  for (const double roughness : { 0.4, 0.8 })
  {
    const std::vector<float> field = diamondSquare(levels, roughness, 9);
    const double expected = -2.0 * roughness - 1.0;
    const double slope = spectralSlope(field, n, size, 1.0 / 256, 1.0 / 8);
    std::printf("diamond-square H %.2f: spectral slope %.3f, expected %.3f\n", roughness, slope, expected);
    EXPECT_NEAR(slope, expected, 0.1 * std::fabs(expected)) << "H " << roughness;
  }
}

TEST(FractalSpectrum, TurbulenceAndRidgedStayInTheUnitInterval)
{
  const PerlinNoise noise(4);
  for (const FractalType type : { FractalType::Turbulence, FractalType::Ridged })
  {
    FractalSettings s;
    s.type = type;
    float lo = 1e9f, hi = -1e9f;
    for (int k = 0; k < 20000; ++k)
    {
      const float v = fractal(noise, s, 0.0137f * static_cast<float>(k % 150), 0.0173f * static_cast<float>(k / 150));
      lo = std::fmin(lo, v), hi = std::fmax(hi, v);
    }
    EXPECT_GE(lo, 0.0f);
    EXPECT_LE(hi, 1.0f);
    EXPECT_GT(hi - lo, 0.2f); // not constant
  }
}
} // namespace
