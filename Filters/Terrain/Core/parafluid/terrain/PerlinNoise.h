#pragma once
// Ken Perlin's improved gradient noise (Perlin 2002, "Improving Noise"): quintic fade
// 6t^5 - 15t^4 + 10t^3 (so value, gradient and second derivative are continuous across cell
// borders), a permutation of 0..255 shuffled from a seed, and gradients of equal length sqrt(2).
// The noise is 0 at every lattice point.
#include <array>
#include <cstdint>
#include <vector>

namespace parafluid::terrain
{
/// Fade 6t^5 - 15t^4 + 10t^3 and its derivative.
inline float perlinFade(float t)
{
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
inline float perlinFadeDerivative(float t)
{
  return 30.0f * t * t * (t * (t - 2.0f) + 1.0f);
}

class PerlinNoise
{
public:
  /// The permutation is a Fisher-Yates shuffle of 0..255 driven by a SplitMix64 stream of `seed`:
  /// the same seed gives the same noise on every machine and thread count.
  explicit PerlinNoise(std::uint64_t seed = 0);

  /// 2-D noise; |value| <= kBound2D. Inline: fractal sums call it in their innermost loop.
  float noise(float x, float y) const
  {
    const float fx = floorFast(x), fy = floorFast(y);
    const int ix = static_cast<int>(fx) & 255, iy = static_cast<int>(fy) & 255;
    x -= fx, y -= fy;
    const float u = perlinFade(x), v = perlinFade(y);
    const int a = this->hash(ix) + iy, b = this->hash(ix + 1) + iy;
    const float n00 = gradient2(this->hash(a), x, y), n10 = gradient2(this->hash(b), x - 1.0f, y);
    const float n01 = gradient2(this->hash(a + 1), x, y - 1.0f), n11 = gradient2(this->hash(b + 1), x - 1.0f, y - 1.0f);
    const float lower = n00 + u * (n10 - n00), upper = n01 + u * (n11 - n01);
    return lower + v * (upper - lower);
  }
  /// out[i] += amplitude * noise(x[i], y[i]) (|noise| with `absolute`) for i < n: the fractal
  /// sums' inner loop. On CPUs with AVX2 eight samples at a time (gathers from the permutation);
  /// the same operations in the same order without fused multiply-adds, so the values are those
  /// of noise() one by one, bit for bit.
  void accumulate(const float* x, const float* y, int n, float amplitude, bool absolute, float* out) const;
  /// True when accumulate() runs 8-wide (AVX2) on this CPU.
  static bool vectorised();

  /// 3-D noise; |value| <= kBound3D.
  float noise(float x, float y, float z) const;
  /// 2-D noise and its analytic gradient (d/dx, d/dy).
  float noise(float x, float y, float gradient[2]) const;

  /// Largest |value| Perlin noise can take with gradients of length |g| in n dimensions is
  /// |g| sqrt(n) / 2 (reached only in the limit; every gradient here has |g| = sqrt(2)).
  static constexpr float kBound2D = 1.0f;       // sqrt(2) * sqrt(2) / 2
  static constexpr float kBound3D = 1.2247449f; // sqrt(2) * sqrt(3) / 2

  /// floor() for |x| < 2^31, without the library call.
  static float floorFast(float x)
  {
    const float t = static_cast<float>(static_cast<int>(x));
    return t - static_cast<float>(t > x); // no branch: keeps row loops vectorisable
  }
  /// g . (x, y) for the gradient picked by the low 3 bits of h: the four diagonals (+-1, +-1)
  /// and the four axes (+-sqrt 2, 0), (0, +-sqrt 2), all of length sqrt 2.
  static float gradient2(int h, float x, float y)
  {
    // A table, not a switch: the gradient index is random, and a branch on it mispredicts half
    // the time (a switch made the noise 4x slower).
    static constexpr float gx[8] = { 1.0f, -1.0f, 1.0f, -1.0f, 1.41421356f, -1.41421356f, 0.0f, 0.0f };
    static constexpr float gy[8] = { 1.0f, 1.0f, -1.0f, -1.0f, 0.0f, 0.0f, 1.41421356f, -1.41421356f };
    return gx[h & 7] * x + gy[h & 7] * y;
  }

private:
  int hash(int i) const { return this->Permutation[static_cast<unsigned>(i) & 511u]; }
  std::array<std::int32_t, 512> Permutation{};
  /// Corner hashes tabulated: Corners[x * kCornerStride + y] = P[P[x] + y] for x, y in 0..256
  /// (P: the doubled permutation), the value noise() computes for the corner (x, y) of a cell.
  /// The batched evaluation reads a corner and its neighbour in y with one 2-byte load.
  static constexpr int kCornerStride = 258;
  std::vector<std::uint8_t> Corners;
};

/// SplitMix64: a 64-bit hash / stream step (Steele, Lea & Flood 2014) used for every random
/// choice in the terrain core, so results depend on the seed and an index, never on scheduling.
inline std::uint64_t splitMix64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
/// A uniform number in [0, 1) from a hash value.
inline double unitFromHash(std::uint64_t h)
{
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}
} // namespace parafluid::terrain
