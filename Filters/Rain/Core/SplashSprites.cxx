#include "parafluid/rain/SplashSprites.h"

#include "private/DropRandom.h"

#include <algorithm>
#include <cmath>

namespace parafluid::rain
{
SplashKind splashKindForSlope(double slopeDegrees, bool onWater)
{
  if (onWater || slopeDegrees < 15.0)
  {
    return SplashKind::Flat;
  }
  return slopeDegrees < 40.0 ? SplashKind::Sloped : SplashKind::Steep;
}

namespace
{
/// Adds a soft disc (Gaussian edge) of radius r at (x, y) in sprite units [0, 1]^2 with opacity a.
void disc(std::vector<float>& coverage, int size, double x, double y, double r, double a)
{
  const int x0 = std::max(0, static_cast<int>((x - 2 * r) * size)),
            x1 = std::min(size - 1, static_cast<int>((x + 2 * r) * size));
  const int y0 = std::max(0, static_cast<int>((y - 2 * r) * size)),
            y1 = std::min(size - 1, static_cast<int>((y + 2 * r) * size));
  for (int j = y0; j <= y1; ++j)
  {
    for (int i = x0; i <= x1; ++i)
    {
      const double dx = (i + 0.5) / size - x, dy = (j + 0.5) / size - y;
      const double q = (dx * dx + dy * dy) / (r * r);
      float& c = coverage[static_cast<std::size_t>(j) * size + i];
      c = static_cast<float>(1.0 - (1.0 - c) * (1.0 - a * std::exp(-q * q)));
    }
  }
}

/// One frame: droplets thrown from the impact point (0.5, 0) on ballistic arcs. `lean` moves the
/// launch directions downhill (+x), `spread` is the crown's opening.
void frame(std::vector<float>& coverage, int size, int sequence, int f)
{
  const double t = (f + 0.5) / kSplashFrames; // 0..1 of the splash's life
  const double fade = 1.0 - 0.8 * t;
  const int droplets = 28;
  const double lean = sequence == 0 ? 0.0 : (sequence == 1 ? 0.35 : 0.9);
  for (int k = 0; k < droplets; ++k)
  {
    double u, v;
    detail::uniformPair(97, static_cast<std::uint64_t>(sequence), static_cast<std::uint64_t>(k), 5, u, v);
    // Launch angle from the vertical, mostly outward (a crown), leaning downhill.
    const double side = k % 2 == 0 ? 1.0 : -1.0;
    double angle = side * (0.35 + 0.55 * u) + lean * (1.0 - 0.5 * u);
    if (sequence == 2)
    {
      angle = 0.6 + 0.8 * u; // all downhill
    }
    const double speed = 0.9 + 0.5 * v;
    const double x = 0.5 + 0.45 * speed * std::sin(angle) * t + (sequence == 2 ? 0.25 * t * t : 0.0);
    const double y = std::max(0.0, 0.02 + 1.6 * speed * std::cos(angle) * t - 1.7 * t * t);
    disc(coverage, size, x, y, 0.018 + 0.012 * v, 0.9 * fade);
  }
  // The crown's wall (flat and sloped) or the sheet of water (steep) near the impact.
  const double rise = std::sin(3.14159265 * std::min(1.0, t * 1.4));
  for (int k = -8; k <= 8; ++k)
  {
    const double s = k / 8.0;
    const double x = 0.5 + (sequence == 2 ? 0.2 * t + 0.15 * s : (0.12 + 0.2 * t) * s + 0.1 * lean * t);
    const double height = sequence == 2 ? 0.05 * rise : 0.18 * rise * (0.6 + 0.4 * s * s);
    for (int m = 0; m < 4; ++m)
    {
      disc(coverage, size, x, 0.015 + height * m / 3.0, 0.03, 0.35 * fade * rise);
    }
  }
  if (sequence == 0 && t < 0.7)
  {
    // The central jet of a drop on flat ground (a Worthington jet).
    const double top = 0.45 * std::sin(3.14159265 * t / 0.7);
    for (int m = 0; m < 6; ++m)
    {
      disc(coverage, size, 0.5, top * m / 5.0, 0.025, 0.6 * fade);
    }
  }
}
} // namespace

std::vector<std::uint8_t> splashAtlas(int size)
{
  const int width = kSplashFrames * size, height = kSplashSequences * size;
  std::vector<std::uint8_t> atlas(static_cast<std::size_t>(width) * height * 4, 0);
  std::vector<float> coverage(static_cast<std::size_t>(size) * size);
  for (int s = 0; s < kSplashSequences; ++s)
  {
    for (int f = 0; f < kSplashFrames; ++f)
    {
      std::fill(coverage.begin(), coverage.end(), 0.0f);
      frame(coverage, size, s, f);
      for (int j = 0; j < size; ++j)
      {
        for (int i = 0; i < size; ++i)
        {
          const std::size_t texel =
            (static_cast<std::size_t>(s * size + j) * width + static_cast<std::size_t>(f * size + i)) * 4;
          const float c = coverage[static_cast<std::size_t>(j) * size + i];
          atlas[texel] = atlas[texel + 1] = atlas[texel + 2] = 255;
          atlas[texel + 3] = static_cast<std::uint8_t>(std::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f);
        }
      }
    }
  }
  return atlas;
}
} // namespace parafluid::rain
