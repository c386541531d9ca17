// The neighbour search's inner loop (CandidateBuffer::findHits): distances to every candidate and
// the positions of those inside the support, in candidate order. The AVX-512 copy packs the hits
// with a compress store, 16 candidates an instruction, where the scalar loop took one (the
// packing was half of a δ-SPH step at 90 neighbours: about 15 % of the candidates are hits).
#include "private/NeighbourCandidates.h"

#include "parafluid/common/SimdDispatch.h"

#include <immintrin.h>

namespace parafluid::sph::detail
{
namespace
{
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
                                                     std::uint32_t* hits)
{
  const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
  const __m512 limit = _mm512_set1_ps(h2);
  __m512i index = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i sixteen = _mm512_set1_epi32(16);
  std::uint32_t count = 0;
  for (std::uint32_t j = 0; j < size; j += 16)
  {
    const std::uint32_t left = size - j;
    const __mmask16 valid = left >= 16 ? static_cast<__mmask16>(0xFFFF) : static_cast<__mmask16>((1u << left) - 1u);
    const __m512 dx = _mm512_sub_ps(qx, _mm512_maskz_loadu_ps(valid, px + j));
    const __m512 dy = _mm512_sub_ps(qy, _mm512_maskz_loadu_ps(valid, py + j));
    const __m512 dz = _mm512_sub_ps(qz, _mm512_maskz_loadu_ps(valid, pz + j));
    const __m512 d = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
    _mm512_mask_storeu_ps(r2 + j, valid, d);
    const __mmask16 inside = _mm512_mask_cmp_ps_mask(valid, d, limit, _CMP_LT_OQ);
    _mm512_mask_compressstoreu_epi32(hits + count, inside, index);
    count += static_cast<std::uint32_t>(__builtin_popcount(inside));
    index = _mm512_add_epi32(index, sixteen);
  }
  return count;
}
} // namespace

std::uint32_t findHitsKernel(const float* x, const float* y, const float* z, std::uint32_t size, const float q[3],
                             float h2, float* distanceSquared, std::uint32_t* hits)
{
  std::uint32_t count = 0;
  switch (common::simdLevel())
  {
    case common::SimdLevel::Avx512:
      return findHitsAvx512(x, y, z, size, q, h2, distanceSquared, hits);
    case common::SimdLevel::Avx2:
      findHitsAvx2(x, y, z, size, q, h2, distanceSquared, hits, &count);
      return count;
    default:
      findHitsBaseline(x, y, z, size, q, h2, distanceSquared, hits, &count);
      return count;
  }
}
} // namespace parafluid::sph::detail
