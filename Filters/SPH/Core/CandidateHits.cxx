// The neighbour search's inner loops: the copy of a cell's candidates (CandidateBuffer::gather),
// the distances to every candidate and the positions of those inside the support, in candidate
// order (CandidateBuffer::findHits), and the same among a list of them (findImageHits). The
// AVX-512 copies pack what they keep with a compress, 16 candidates an instruction, where the
// scalar loop took one (the packing was half of a δ-SPH step at 90 neighbours: about 15 % of the
// candidates are hits).
#include "private/NeighbourCandidates.h"

#include "parafluid/common/SimdDispatch.h"

#include <immintrin.h>

namespace parafluid::sph::detail
{
namespace
{
/// The lanes of a 16-wide chunk that hold one of the `left` values still to do.
__attribute__((always_inline)) inline __mmask16 lanesLeft(std::uint32_t left)
{
  return left >= 16 ? static_cast<__mmask16>(0xFFFF) : static_cast<__mmask16>((1u << left) - 1u);
}

__attribute__((always_inline)) inline void findHitsBody(const float* px, const float* py, const float* pz,
                                                        std::uint32_t size, const float* q, float h2, float* r2,
                                                        std::uint32_t* hits, std::uint32_t* count)
{
#pragma omp simd
  for (std::uint32_t j = 0; j < size; ++j)
  {
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    r2[j] = dx * dx + dy * dy + dz * dz;
  }
  std::uint32_t n = 0;
  for (std::uint32_t j = 0; j < size; ++j)
  {
    hits[n] = j;
    n += r2[j] < h2 ? 1u : 0u;
  }
  *count = n;
}

PARAFLUID_TARGET_AVX2 void findHitsAvx2(const float* px, const float* py, const float* pz, std::uint32_t size,
                                        const float* q, float h2, float* r2, std::uint32_t* hits, std::uint32_t* count)
{
  findHitsBody(px, py, pz, size, q, h2, r2, hits, count);
}

void findHitsBaseline(const float* px, const float* py, const float* pz, std::uint32_t size, const float* q, float h2,
                      float* r2, std::uint32_t* hits, std::uint32_t* count)
{
  findHitsBody(px, py, pz, size, q, h2, r2, hits, count);
}

// Products and sums as separate roundings (the file is built with -ffp-contract=off), as the
// baseline copy computes them.
PARAFLUID_TARGET_AVX512 std::uint32_t findHitsAvx512(const float* px, const float* py, const float* pz,
                                                     std::uint32_t size, const float q[3], float h2, float* r2,
                                                     std::uint32_t* hits, bool keepDistances)
{
  const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
  const __m512 limit = _mm512_set1_ps(h2);
  __m512i index = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i sixteen = _mm512_set1_epi32(16);
  std::uint32_t count = 0;
  for (std::uint32_t j = 0; j < size; j += 16)
  {
    const __mmask16 valid = lanesLeft(size - j);
    const __m512 dx = _mm512_sub_ps(qx, _mm512_maskz_loadu_ps(valid, px + j));
    const __m512 dy = _mm512_sub_ps(qy, _mm512_maskz_loadu_ps(valid, py + j));
    const __m512 dz = _mm512_sub_ps(qz, _mm512_maskz_loadu_ps(valid, pz + j));
    const __m512 d = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
    if (keepDistances)
    {
      _mm512_mask_storeu_ps(r2 + j, valid, d);
    }
    const __mmask16 inside = _mm512_mask_cmp_ps_mask(valid, d, limit, _CMP_LT_OQ);
    // Compressed in a register and stored whole (hits has 16 slots of room past the candidates):
    // a compress straight to memory costs several times as much on Intel cores.
    _mm512_storeu_si512(hits + count, _mm512_maskz_compress_epi32(inside, index));
    count += static_cast<std::uint32_t>(__builtin_popcount(inside));
    index = _mm512_add_epi32(index, sixteen);
  }
  return count;
}

/// The candidates' copy (CandidateBuffer::gather) drops a particle where its distance² to the
/// cell's box is reach2 or more (and keeps it where that is NaN, as the scalar test `>= reach2`
/// did). Its distance to the box along one axis:
__attribute__((always_inline)) inline float boxDistance(float p, float lo, float hi)
{
  const float below = lo - p, above = p - hi;
  const float d = below > 0.0f ? below : 0.0f;
  return above > d ? above : d;
}

std::uint32_t appendNearBoxScalar(const float* px, const float* py, const float* pz, std::uint32_t b, std::uint32_t e,
                                  const float shift[3], const float lo[3], const float hi[3], float reach2,
                                  const float* const* sources, int channels, float* x, float* y, float* z,
                                  float* const* channel, std::uint32_t size)
{
  for (std::uint32_t j = b; j < e; ++j)
  {
    const float cx = px[j] + shift[0], cy = py[j] + shift[1], cz = pz[j] + shift[2];
    const float dx = boxDistance(cx, lo[0], hi[0]);
    const float dy = boxDistance(cy, lo[1], hi[1]);
    const float dz = boxDistance(cz, lo[2], hi[2]);
    if (dx * dx + dy * dy + dz * dz >= reach2)
    {
      continue;
    }
    x[size] = cx;
    y[size] = cy;
    z[size] = cz;
    for (int k = 0; k < channels; ++k)
    {
      channel[k][size] = sources[k][j];
    }
    ++size;
  }
  return size;
}

PARAFLUID_TARGET_AVX512 std::uint32_t appendNearBoxAvx512(const float* px, const float* py, const float* pz,
                                                          std::uint32_t b, std::uint32_t e, const float shift[3],
                                                          const float lo[3], const float hi[3], float reach2,
                                                          const float* const* sources, int channels, float* x, float* y,
                                                          float* z, float* const* channel, std::uint32_t size)
{
  const __m512 zero = _mm512_setzero_ps(), limit = _mm512_set1_ps(reach2);
  const __mmask16 all = 0xFFFF;
  const __m512 shifts[3] = { _mm512_set1_ps(shift[0]), _mm512_set1_ps(shift[1]), _mm512_set1_ps(shift[2]) };
  const __m512 low[3] = { _mm512_set1_ps(lo[0]), _mm512_set1_ps(lo[1]), _mm512_set1_ps(lo[2]) };
  const __m512 high[3] = { _mm512_set1_ps(hi[0]), _mm512_set1_ps(hi[1]), _mm512_set1_ps(hi[2]) };
  const float* source[3] = { px, py, pz };
  float* target[3] = { x, y, z };
  for (std::uint32_t j = b; j < e; j += 16)
  {
    const __mmask16 valid = lanesLeft(e - j);
    __m512 p[3], d2 = zero;
    for (int a = 0; a < 3; ++a)
    {
      p[a] = _mm512_add_ps(_mm512_maskz_loadu_ps(valid, source[a] + j), shifts[a]);
      // max(a, b) is a > b ? a : b, as boxDistance (the masked form: GCC 12 warns that the
      // plain one's undefined pass-through may be used uninitialised).
      const __m512 below = _mm512_maskz_max_ps(all, _mm512_sub_ps(low[a], p[a]), zero);
      const __m512 d = _mm512_maskz_max_ps(all, _mm512_sub_ps(p[a], high[a]), below);
      d2 = a == 0 ? _mm512_mul_ps(d, d) : _mm512_add_ps(d2, _mm512_mul_ps(d, d));
    }
    const __mmask16 keep = _mm512_mask_cmp_ps_mask(valid, d2, limit, _CMP_NGE_UQ);
    // Compressed in registers and stored whole (16 values of room past the end).
    for (int a = 0; a < 3; ++a)
    {
      _mm512_storeu_ps(target[a] + size, _mm512_maskz_compress_ps(keep, p[a]));
    }
    for (int k = 0; k < channels; ++k)
    {
      _mm512_storeu_ps(channel[k] + size, _mm512_maskz_compress_ps(keep, _mm512_maskz_loadu_ps(valid, sources[k] + j)));
    }
    size += static_cast<std::uint32_t>(__builtin_popcount(keep));
  }
  return size;
}

std::uint32_t findHitsAmongScalar(const float* x, const float* y, const float* z, const std::uint32_t* among,
                                  std::uint32_t amongCount, const float q[3], float h2, std::uint32_t* out)
{
  std::uint32_t count = 0;
  for (std::uint32_t k = 0; k < amongCount; ++k)
  {
    const std::uint32_t j = among[k];
    const float dx = q[0] - x[j], dy = q[1] - y[j], dz = q[2] - z[j];
    const float d = dx * dx + dy * dy + dz * dz;
    out[count] = j;
    count += d < h2 ? 1u : 0u;
  }
  return count;
}

PARAFLUID_TARGET_AVX512 std::uint32_t findHitsAmongAvx512(const float* x, const float* y, const float* z,
                                                          const std::uint32_t* among, std::uint32_t amongCount,
                                                          const float q[3], float h2, std::uint32_t* out)
{
  const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
  const __m512 limit = _mm512_set1_ps(h2), zero = _mm512_setzero_ps();
  std::uint32_t count = 0;
  for (std::uint32_t k = 0; k < amongCount; k += 16)
  {
    const __mmask16 valid = lanesLeft(amongCount - k);
    const __m512i index = _mm512_maskz_loadu_epi32(valid, among + k);
    const __m512 dx = _mm512_sub_ps(qx, _mm512_mask_i32gather_ps(zero, valid, index, x, 4));
    const __m512 dy = _mm512_sub_ps(qy, _mm512_mask_i32gather_ps(zero, valid, index, y, 4));
    const __m512 dz = _mm512_sub_ps(qz, _mm512_mask_i32gather_ps(zero, valid, index, z, 4));
    const __m512 d = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
    const __mmask16 inside = _mm512_mask_cmp_ps_mask(valid, d, limit, _CMP_LT_OQ);
    _mm512_storeu_si512(out + count, _mm512_maskz_compress_epi32(inside, index));
    count += static_cast<std::uint32_t>(__builtin_popcount(inside));
  }
  return count;
}
} // namespace

std::uint32_t findHitsAmongKernel(const float* x, const float* y, const float* z, const std::uint32_t* among,
                                  std::uint32_t amongCount, const float q[3], float h2, std::uint32_t* out)
{
  if (common::simdLevel() == common::SimdLevel::Avx512)
  {
    return findHitsAmongAvx512(x, y, z, among, amongCount, q, h2, out);
  }
  return findHitsAmongScalar(x, y, z, among, amongCount, q, h2, out);
}

std::uint32_t appendNearBoxKernel(const float* px, const float* py, const float* pz, std::uint32_t b, std::uint32_t e,
                                  const float shift[3], const float lo[3], const float hi[3], float reach2,
                                  const float* const* sources, int channels, float* x, float* y, float* z,
                                  float* const* channel, std::uint32_t size)
{
  if (common::simdLevel() == common::SimdLevel::Avx512)
  {
    return appendNearBoxAvx512(px, py, pz, b, e, shift, lo, hi, reach2, sources, channels, x, y, z, channel, size);
  }
  return appendNearBoxScalar(px, py, pz, b, e, shift, lo, hi, reach2, sources, channels, x, y, z, channel, size);
}

std::uint32_t findHitsKernel(const float* x, const float* y, const float* z, std::uint32_t size, const float q[3],
                             float h2, float* distanceSquared, std::uint32_t* hits, bool keepDistances)
{
  std::uint32_t count = 0;
  switch (common::simdLevel())
  {
    case common::SimdLevel::Avx512:
      return findHitsAvx512(x, y, z, size, q, h2, distanceSquared, hits, keepDistances);
    case common::SimdLevel::Avx2:
      findHitsAvx2(x, y, z, size, q, h2, distanceSquared, hits, &count);
      return count;
    default:
      findHitsBaseline(x, y, z, size, q, h2, distanceSquared, hits, &count);
      return count;
  }
}
} // namespace parafluid::sph::detail
