#include "parafluid/terrain/PerlinNoise.h"

#include <cmath>
#include <cstring>
#include <utility>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PARAFLUID_TERRAIN_AVX2 1
#endif

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
  this->Corners.assign(static_cast<std::size_t>(kCornerStride) * 257, 0);
  for (int x = 0; x <= 256; ++x)
  {
    for (int y = 0; y <= 256; ++y)
    {
      this->Corners[static_cast<std::size_t>(x) * kCornerStride + y] =
        static_cast<std::uint8_t>(this->hash(this->hash(x) + y));
    }
  }
}

namespace
{
#ifdef PARAFLUID_TERRAIN_AVX2
// Lambdas do not inherit a function's target, so the lane helpers are functions of their own.
#define PARAFLUID_AVX2 __attribute__((target("avx2"), always_inline)) inline
PARAFLUID_AVX2 __m256 floorAvx2(__m256 v)
{
  const __m256 t = _mm256_cvtepi32_ps(_mm256_cvttps_epi32(v));
  return _mm256_sub_ps(t, _mm256_and_ps(_mm256_cmp_ps(t, v, _CMP_GT_OQ), _mm256_set1_ps(1.0f)));
}
PARAFLUID_AVX2 __m256 fadeAvx2(__m256 t)
{
  const __m256 cube = _mm256_mul_ps(_mm256_mul_ps(t, t), t);
  const __m256 inner = _mm256_sub_ps(_mm256_mul_ps(t, _mm256_set1_ps(6.0f)), _mm256_set1_ps(15.0f));
  return _mm256_mul_ps(cube, _mm256_add_ps(_mm256_mul_ps(t, inner), _mm256_set1_ps(10.0f)));
}
/// corners[index] and corners[index + 1] for 8 lanes: one 2-byte load per lane gives a corner's
/// hash and that of its neighbour in y. Scalar loads rather than vpgatherdd: on the machine
/// measured (Testing/Benchmarks/README.md) gathers made the noise 2.6x slower.
PARAFLUID_AVX2 void cornerPairAvx2(const std::uint8_t* corners, __m256i index, __m256i& first, __m256i& second)
{
  alignas(32) std::int32_t lanes[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), index);
  std::uint16_t pair[8];
  for (int k = 0; k < 8; ++k)
  {
    std::memcpy(&pair[k], corners + lanes[k], sizeof(std::uint16_t));
  }
  // Little-endian: the low byte is corners[index].
  const __m256i both = _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(pair)));
  first = _mm256_and_si256(both, _mm256_set1_epi32(255));
  second = _mm256_srli_epi32(both, 8);
}
PARAFLUID_AVX2 __m256 gradientAvx2(__m256i h, __m256 gx, __m256 gy)
{
  constexpr float r2 = 1.41421356f;
  const __m256i k = _mm256_and_si256(h, _mm256_set1_epi32(7));
  const __m256 xTable = _mm256_setr_ps(1.0f, -1.0f, 1.0f, -1.0f, r2, -r2, 0.0f, 0.0f);
  const __m256 yTable = _mm256_setr_ps(1.0f, 1.0f, -1.0f, -1.0f, 0.0f, 0.0f, r2, -r2);
  return _mm256_add_ps(_mm256_mul_ps(_mm256_permutevar8x32_ps(xTable, k), gx),
                       _mm256_mul_ps(_mm256_permutevar8x32_ps(yTable, k), gy));
}

/// PerlinNoise::noise over 8 lanes, operation for operation (compiled for AVX2 without FMA, so no
/// multiply-add is fused and every rounding matches the scalar code). Returns the samples done
/// (a multiple of 8).
__attribute__((target("avx2"))) int accumulateAvx2(const std::uint8_t* corners, int stride, const float* x,
                                                   const float* y, int n, float amplitude, bool absolute, float* out)
{
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256i mask255 = _mm256_set1_epi32(255);
  const __m256 scale = _mm256_set1_ps(amplitude), sign = _mm256_set1_ps(-0.0f);
  int i = 0;
  for (; i + 8 <= n; i += 8)
  {
    __m256 px = _mm256_loadu_ps(x + i), py = _mm256_loadu_ps(y + i);
    const __m256 fx = floorAvx2(px), fy = floorAvx2(py);
    const __m256i ix = _mm256_and_si256(_mm256_cvttps_epi32(fx), mask255);
    const __m256i iy = _mm256_and_si256(_mm256_cvttps_epi32(fy), mask255);
    px = _mm256_sub_ps(px, fx), py = _mm256_sub_ps(py, fy);
    const __m256 u = fadeAvx2(px), v = fadeAvx2(py);
    __m256i h00, h01, h10, h11;
    const __m256i corner = _mm256_add_epi32(_mm256_mullo_epi32(ix, _mm256_set1_epi32(stride)), iy);
    cornerPairAvx2(corners, corner, h00, h01);
    cornerPairAvx2(corners, _mm256_add_epi32(corner, _mm256_set1_epi32(stride)), h10, h11);
    const __m256 xm = _mm256_sub_ps(px, one), ym = _mm256_sub_ps(py, one);
    const __m256 n00 = gradientAvx2(h00, px, py), n10 = gradientAvx2(h10, xm, py);
    const __m256 n01 = gradientAvx2(h01, px, ym), n11 = gradientAvx2(h11, xm, ym);
    const __m256 lower = _mm256_add_ps(n00, _mm256_mul_ps(u, _mm256_sub_ps(n10, n00)));
    const __m256 upper = _mm256_add_ps(n01, _mm256_mul_ps(u, _mm256_sub_ps(n11, n01)));
    __m256 value = _mm256_add_ps(lower, _mm256_mul_ps(v, _mm256_sub_ps(upper, lower)));
    if (absolute)
    {
      value = _mm256_andnot_ps(sign, value);
    }
    _mm256_storeu_ps(out + i, _mm256_add_ps(_mm256_loadu_ps(out + i), _mm256_mul_ps(scale, value)));
  }
  return i;
}
#endif

bool cpuHasAvx2()
{
#ifdef PARAFLUID_TERRAIN_AVX2
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}
} // namespace

bool PerlinNoise::vectorised()
{
  return cpuHasAvx2();
}

void PerlinNoise::accumulate(const float* x, const float* y, int n, float amplitude, bool absolute, float* out) const
{
  int i = 0;
#ifdef PARAFLUID_TERRAIN_AVX2
  if (cpuHasAvx2())
  {
    i = accumulateAvx2(this->Corners.data(), kCornerStride, x, y, n, amplitude, absolute, out);
  }
#endif
  for (; i < n; ++i)
  {
    const float v = this->noise(x[i], y[i]);
    out[i] += amplitude * (absolute ? std::fabs(v) : v);
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
