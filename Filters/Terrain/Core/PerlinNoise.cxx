#include "parafluid/terrain/PerlinNoise.h"

#include <utility>

namespace parafluid::terrain
{
PerlinNoise::PerlinNoise(std::uint64_t seed)
{
  std::array<std::uint8_t, 256> p{};
  for (int i = 0; i < 256; ++i)
  {
    p[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
  }
  std::uint64_t state = seed;
  for (int i = 255; i > 0; --i)
  {
    state = splitMix64(state);
    const auto j = static_cast<int>(state % static_cast<std::uint64_t>(i + 1));
    std::swap(p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]);
  }
  // Doubled so hash(hash(i) + j) never needs a second mask.
  for (std::size_t i = 0; i < 512; ++i)
  {
    this->Permutation[i] = p[i & 255];
  }
}

float PerlinNoise::noise(float x, float y, float gradient[2]) const
{
  const float fx = floorFast(x), fy = floorFast(y);
  const int ix = static_cast<int>(fx) & 255, iy = static_cast<int>(fy) & 255;
  x -= fx, y -= fy;
  const float u = perlinFade(x), v = perlinFade(y);
  const float du = perlinFadeDerivative(x), dv = perlinFadeDerivative(y);
  const int a = this->hash(ix) + iy, b = this->hash(ix + 1) + iy;
  const int h00 = this->hash(a), h10 = this->hash(b), h01 = this->hash(a + 1), h11 = this->hash(b + 1);
  const float n00 = gradient2(h00, x, y), n10 = gradient2(h10, x - 1.0f, y);
  const float n01 = gradient2(h01, x, y - 1.0f), n11 = gradient2(h11, x - 1.0f, y - 1.0f);
  // The gradient vectors themselves: d(g . d)/dx and d/dy.
  const auto gx = [](int h) { return gradient2(h, 1.0f, 0.0f); };
  const auto gy = [](int h) { return gradient2(h, 0.0f, 1.0f); };
  // n = n00 + u (n10 - n00) + v (n01 - n00) + u v (n00 - n10 - n01 + n11)
  const float k1 = n10 - n00, k2 = n01 - n00, k3 = n00 - n10 - n01 + n11;
  const float gxs =
    gx(h00) + u * (gx(h10) - gx(h00)) + v * (gx(h01) - gx(h00)) + u * v * (gx(h00) - gx(h10) - gx(h01) + gx(h11));
  const float gys =
    gy(h00) + u * (gy(h10) - gy(h00)) + v * (gy(h01) - gy(h00)) + u * v * (gy(h00) - gy(h10) - gy(h01) + gy(h11));
  gradient[0] = gxs + du * (k1 + v * k3);
  gradient[1] = gys + dv * (k2 + u * k3);
  return n00 + u * k1 + v * k2 + u * v * k3;
}

namespace
{
/// Perlin's 12 edge gradients (+-1, +-1, 0) and permutations, with 4 repeated to make 16.
float gradient3(int h, float x, float y, float z)
{
  switch (h & 15)
  {
    case 0:
      return x + y;
    case 1:
      return -x + y;
    case 2:
      return x - y;
    case 3:
      return -x - y;
    case 4:
      return x + z;
    case 5:
      return -x + z;
    case 6:
      return x - z;
    case 7:
      return -x - z;
    case 8:
      return y + z;
    case 9:
      return -y + z;
    case 10:
      return y - z;
    case 11:
      return -y - z;
    case 12:
      return x + y;
    case 13:
      return -y + z;
    case 14:
      return -x + y;
    default:
      return -y - z;
  }
}
float lerp(float t, float a, float b)
{
  return a + t * (b - a);
}
} // namespace

float PerlinNoise::noise(float x, float y, float z) const
{
  const float fx = floorFast(x), fy = floorFast(y), fz = floorFast(z);
  const int ix = static_cast<int>(fx) & 255, iy = static_cast<int>(fy) & 255, iz = static_cast<int>(fz) & 255;
  x -= fx, y -= fy, z -= fz;
  const float u = perlinFade(x), v = perlinFade(y), w = perlinFade(z);
  const int a = this->hash(ix) + iy, aa = this->hash(a) + iz, ab = this->hash(a + 1) + iz;
  const int b = this->hash(ix + 1) + iy, ba = this->hash(b) + iz, bb = this->hash(b + 1) + iz;
  return lerp(
    w,
    lerp(v, lerp(u, gradient3(this->hash(aa), x, y, z), gradient3(this->hash(ba), x - 1, y, z)),
         lerp(u, gradient3(this->hash(ab), x, y - 1, z), gradient3(this->hash(bb), x - 1, y - 1, z))),
    lerp(v, lerp(u, gradient3(this->hash(aa + 1), x, y, z - 1), gradient3(this->hash(ba + 1), x - 1, y, z - 1)),
         lerp(u, gradient3(this->hash(ab + 1), x, y - 1, z - 1), gradient3(this->hash(bb + 1), x - 1, y - 1, z - 1))));
}
} // namespace parafluid::terrain
