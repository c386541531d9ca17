#include "parafluid/terrain/DiamondSquare.h"

#include "parafluid/terrain/PerlinNoise.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace parafluid::terrain
{
int diamondSquareLevels(int points)
{
  int levels = 1;
  while ((1 << levels) + 1 < points && levels < 30)
  {
    ++levels;
  }
  return levels;
}

std::vector<float> diamondSquare(int levels, double roughness, std::uint64_t seed)
{
  if (levels < 1 || levels > 15)
  {
    throw std::invalid_argument("diamond-square: levels must be 1 to 15 (grids of 3 to 32769 points), got " +
                                std::to_string(levels));
  }
  if (!(roughness >= 0.0 && roughness <= 2.0))
  {
    throw std::invalid_argument("diamond-square: Roughness H must be from 0 to 2, got " + std::to_string(roughness));
  }
  const int size = (1 << levels) + 1;
  std::vector<float> h(static_cast<std::size_t>(size) * size, 0.0f);
  const auto at = [&](int i, int j) -> float& { return h[static_cast<std::size_t>(j) * size + i]; };
  const std::uint64_t key = splitMix64(seed ^ 0x5851f42d4c957f2dull);
  // A displacement uniform in [-amplitude, amplitude], a pure function of the node.
  const auto displacement = [&](int i, int j, double amplitude)
  {
    const std::uint64_t hash = splitMix64(key ^ (static_cast<std::uint64_t>(j) << 32 | static_cast<std::uint32_t>(i)));
    return static_cast<float>(amplitude * (2.0 * unitFromHash(hash) - 1.0));
  };
  const int last = size - 1;
  for (int c = 0; c < 4; ++c)
  {
    const int i = (c & 1) * last, j = (c >> 1) * last;
    at(i, j) = displacement(i, j, 1.0);
  }
  const double decay = std::pow(2.0, -roughness);
  double amplitude = decay;
  for (int step = last; step > 1; step /= 2, amplitude *= decay)
  {
    const int half = step / 2;
    // Diamond: centres of the squares of side `step`.
#pragma omp parallel for schedule(static)
    for (int j = half; j < size; j += step)
    {
      for (int i = half; i < size; i += step)
      {
        const float mean =
          0.25f * (at(i - half, j - half) + at(i + half, j - half) + at(i - half, j + half) + at(i + half, j + half));
        at(i, j) = mean + displacement(i, j, amplitude);
      }
    }
    // Square: edge midpoints, from the 4 (or, on the border, 3) nodes of their diamond.
#pragma omp parallel for schedule(static)
    for (int j = 0; j < size; j += half)
    {
      for (int i = ((j / half) % 2 == 0) ? half : 0; i < size; i += step)
      {
        float sum = 0.0f;
        int count = 0;
        if (i >= half)
        {
          sum += at(i - half, j), ++count;
        }
        if (i + half < size)
        {
          sum += at(i + half, j), ++count;
        }
        if (j >= half)
        {
          sum += at(i, j - half), ++count;
        }
        if (j + half < size)
        {
          sum += at(i, j + half), ++count;
        }
        at(i, j) = sum / static_cast<float>(count) + displacement(i, j, amplitude);
      }
    }
  }
  float largest = 0.0f;
  for (const float v : h)
  {
    largest = std::fmax(largest, std::fabs(v));
  }
  if (largest > 0.0f)
  {
    for (float& v : h)
    {
      v /= largest;
    }
  }
  return h;
}
} // namespace parafluid::terrain
