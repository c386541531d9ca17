#pragma once
// Internal to the SPH solver: cell-by-cell neighbour loops over a NeighbourGrid. For each grid cell
// the particles of the 27 cells around it are copied into one contiguous buffer (with whichever
// per-particle values the pass needs), so the pair loops of all particles of that cell run over one
// long array, which vectorises, instead of 9 short ranges.
#include "parafluid/common/NeighbourGrid.h"
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace parafluid::sph::detail
{
inline int threadCount(const SPHParameters& p)
{
#ifdef _OPENMP
  return p.threads > 0 ? p.threads : omp_get_max_threads();
#else
  (void)p;
  return 1;
#endif
}

/// Gathers a into sorted order through scratch, then swaps, so each array is copied once.
template<class T>
void permute(std::vector<T>& a, std::vector<T>& scratch, const std::vector<std::uint32_t>& order, int threads)
{
  const auto n = static_cast<std::int64_t>(order.size());
  scratch.resize(order.size());
  const T* source = a.data();
  T* target = scratch.data();
  const std::uint32_t* o = order.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < n; ++k)
  {
    target[k] = source[o[k]];
  }
  a.swap(scratch);
}

/// distanceSquared[j] = |q - (x, y, z)[j]|^2 for j < size, and hits[0..count) the j (ascending)
/// with distanceSquared[j] < h2; returns count. hits needs room for size + 16 values (the AVX-512
/// copy stores 16 at a time). Without keepDistances the AVX-512 copy does not store the
/// distances (the others always do). Compiled for AVX-512, AVX2 and the baseline (CandidateHits.cxx).
std::uint32_t findHitsKernel(const float* x, const float* y, const float* z, std::uint32_t size, const float q[3],
                             float h2, float* distanceSquared, std::uint32_t* hits, bool keepDistances = true);
/// out[0..count) the among[k] (k < amongCount, in order) with |q - (x, y, z)[among[k]]|^2 < h2,
/// the squares summed as findHitsKernel sums them; returns count. out needs room for amongCount +
/// 16 values. Compiled for AVX-512 and the baseline (CandidateHits.cxx).
std::uint32_t findHitsAmongKernel(const float* x, const float* y, const float* z, const std::uint32_t* among,
                                  std::uint32_t amongCount, const float q[3], float h2, std::uint32_t* out);

/// Up to this many per-particle values ride along with the positions of the candidates.
constexpr int kMaxChannels = 8;

/// The particles b..e (of positions px, py, pz, shifted by `shift`) whose distance² to the box
/// lo..hi is not reach2 or more, appended in order at `size` to x, y, z and, for k < channels,
/// sources[k][j] to channel[k]; returns the new size. Each output needs room for 16 values past
/// the last one written (the AVX-512 copy stores 16 at a time). Compiled for AVX-512 and the
/// baseline (CandidateHits.cxx).
std::uint32_t appendNearBoxKernel(const float* px, const float* py, const float* pz, std::uint32_t b, std::uint32_t e,
                                  const float shift[3], const float lo[3], const float hi[3], float reach2,
                                  const float* const* sources, int channels, float* x, float* y, float* z,
                                  float* const* channel, std::uint32_t size);

struct CandidateBuffer
{
  std::vector<float> x, y, z;
  std::array<std::vector<float>, kMaxChannels> channel;
  std::vector<std::uint32_t> hits;      // buffer positions of the candidates inside the kernel radius
  std::uint32_t hitCount = 0;           // of the last findHits, before any padding
  std::vector<std::uint32_t> imageHits; // the same for a wall image of the last query (findImageHits)
  std::vector<float> distanceSquared;
  std::uint32_t size = 0;

  /// Copies the particles of the 27 cells around (ix, iy, iz) that lie within `reach` of that
  /// cell's box (the others cannot be within reach of any particle in the cell: this drops about
  /// a quarter of them), with the values sources[k][j] into channel[k]. Across a periodic axis
  /// each candidate is shifted by the period it was reached across, so every pair loop sees the
  /// nearest periodic image.
  void gather(const NeighbourGrid& grid, int ix, int iy, int iz, const ParticleState& s, float reach,
              const std::array<const float*, kMaxChannels>& sources, int channels)
  {
    const bool periodic = grid.anyPeriodic();
    const auto& start = grid.cellStart();
    std::uint32_t capacity = 0;
    if (periodic)
    {
      grid.forEachNeighbourCell(ix, iy, iz, [&](std::size_t c, const float*) { capacity += start[c + 1] - start[c]; });
    }
    else
    {
      grid.forEachNeighbourRange(ix, iy, iz, [&](std::uint32_t b, std::uint32_t e) { capacity += e - b; });
    }
    // Room past the candidates: the sentinel candidate that padHits points at, and the 16-value
    // stores of the AVX-512 copies (appendNearBoxKernel, findHitsKernel).
    for (auto* a : { &x, &y, &z, &distanceSquared })
    {
      a->resize(capacity + kHitPadding);
    }
    hits.resize(capacity + kHitPadding);
    imageHits.resize(capacity + kHitPadding);
    std::array<float*, kMaxChannels> targets{};
    for (int k = 0; k < channels; ++k)
    {
      channel[k].resize(capacity + kHitPadding);
      targets[k] = channel[k].data();
    }
    float lo[3], hi[3];
    grid.cellBox(ix, iy, iz, lo, hi);
    const float reach2 = reach * reach;
    size = 0;
    auto append = [&](std::uint32_t b, std::uint32_t e, const float shift[3])
    {
      size = appendNearBoxKernel(s.x.data(), s.y.data(), s.z.data(), b, e, shift, lo, hi, reach2, sources.data(),
                                 channels, x.data(), y.data(), z.data(), targets.data(), size);
    };
    if (periodic)
    {
      grid.forEachNeighbourCell(ix, iy, iz,
                                [&](std::size_t c, const float* shift) { append(start[c], start[c + 1], shift); });
    }
    else
    {
      static const float none[3] = { 0.0f, 0.0f, 0.0f };
      grid.forEachNeighbourRange(ix, iy, iz, [&](std::uint32_t b, std::uint32_t e) { append(b, e, none); });
    }
    // The sentinel: far outside any support, with finite values, so that a pair term carrying the
    // kernel as a factor is zero (the padded loops compute distances from the positions).
    x[size] = y[size] = z[size] = kSentinelPosition;
    for (int k = 0; k < channels; ++k)
    {
      channel[k][size] = 1.0f;
    }
  }

  /// Σ_j (h² − r²)³ over candidates inside h of q (the poly6 sum without its constant).
  float poly6Sum(const float q[3], float h2) const
  {
    const float *px = x.data(), *py = y.data(), *pz = z.data();
    const float qx = q[0], qy = q[1], qz = q[2];
    float sum = 0.0f;
#pragma omp simd reduction(+ : sum)
    for (std::uint32_t j = 0; j < size; ++j)
    {
      const float dx = qx - px[j], dy = qy - py[j], dz = qz - pz[j];
      const float d = std::max(h2 - (dx * dx + dy * dy + dz * dz), 0.0f);
      sum += d * d * d;
    }
    return sum;
  }

  /// Finds the candidates strictly inside radius² h2 of q (typically 15 % of them), so that square
  /// roots and divisions are spent on real neighbours only. Returns their number; hits[0..count)
  /// are their buffer positions and distanceSquared[j] holds |q − x_j|² for every candidate j.
  std::uint32_t findHits(const float q[3], float h2, bool keepDistances = true)
  {
    hitCount =
      findHitsKernel(x.data(), y.data(), z.data(), size, q, h2, distanceSquared.data(), hits.data(), keepDistances);
    return hitCount;
  }

  /// The candidates inside radius² h2 of q, a wall image (a mirror image across box walls) of the
  /// last findHits' query, into imageHits, padded as padHits pads: they are among that query's
  /// hits, since a particle inside the box is nearer to a point inside than to its mirror image,
  /// so only those are searched (90 instead of ~550 candidates at 3 spacings).
  std::uint32_t findImageHits(const float q[3], float h2)
  {
    const std::uint32_t count =
      findHitsAmongKernel(x.data(), y.data(), z.data(), hits.data(), hitCount, q, h2, imageHits.data());
    return pad(imageHits.data(), count);
  }

  /// Pads hits[count..) with the sentinel candidate up to a multiple of kHitPadding and returns
  /// that length: a pair loop over it then runs in whole vectors, where the last few pairs would
  /// otherwise go through the compiler's scalar remainder loop (with 90 neighbours and 16 lanes,
  /// a third of δ-SPH's pair-loop time was there). A pair term that carries the kernel or its
  /// gradient as a factor is exactly zero for the sentinel, 1e15 m from the origin, as long as
  /// its other factors stay finite there (r² ~ 1e30: take quotients such as r² / (r² + η²) whole).
  std::uint32_t padHits(std::uint32_t count)
  {
    return pad(hits.data(), count);
  }
  std::uint32_t pad(std::uint32_t* list, std::uint32_t count) const
  {
    const std::uint32_t padded = (count + kHitPadding - 1) / kHitPadding * kHitPadding;
    for (std::uint32_t n = count; n < padded; ++n)
    {
      list[n] = size;
    }
    return padded;
  }
  static constexpr std::uint32_t kHitPadding = 16;  // the AVX-512 copies' lanes of float
  static constexpr float kSentinelPosition = 1e15f; // [m]
};

/// Runs body(candidates, i) for every particle i, cell by cell in parallel, after gathering into a
/// thread-private buffer the candidates of that cell with the given per-particle channels. Each
/// particle is handled by one thread in a fixed candidate order, so results do not depend on the
/// thread count. Particles whose `skip` flag is set are not visited (a distributed run's ghosts in
/// a pass whose results for them nothing reads), nor are the cells that hold only such particles.
template<class Body>
void forEachParticleByCell(const NeighbourGrid& grid, const ParticleState& s, float reach, int threads,
                           std::initializer_list<const float*> channelSources, Body&& body,
                           const std::uint8_t* skip = nullptr)
{
  std::array<const float*, kMaxChannels> sources{};
  int channels = 0;
  for (const float* c : channelSources)
  {
    sources[channels++] = c;
  }
  const auto& start = grid.cellStart();
  const auto cells = static_cast<std::int64_t>(grid.cellCount());
#pragma omp parallel num_threads(threads)
  {
    CandidateBuffer candidates;
#pragma omp for schedule(dynamic, 64)
    for (std::int64_t c = 0; c < cells; ++c)
    {
      const std::uint32_t begin = start[c];
      const std::uint32_t end = start[c + 1];
      if (begin == end || (skip && std::all_of(skip + begin, skip + end, [](std::uint8_t f) { return f != 0; })))
      {
        continue;
      }
      int ix, iy, iz;
      grid.cellCoordinates(static_cast<std::size_t>(c), ix, iy, iz);
      candidates.gather(grid, ix, iy, iz, s, reach, sources, channels);
      for (std::uint32_t i = begin; i < end; ++i)
      {
        if (!skip || !skip[i])
        {
          body(candidates, i);
        }
      }
    }
  }
}

} // namespace parafluid::sph::detail
