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
/// with distanceSquared[j] < h2; returns count. Compiled for AVX-512, AVX2 and the baseline
/// (CandidateHits.cxx).
std::uint32_t findHitsKernel(const float* x, const float* y, const float* z, std::uint32_t size, const float q[3],
                             float h2, float* distanceSquared, std::uint32_t* hits);

/// Up to this many per-particle values ride along with the positions of the candidates.
constexpr int kMaxChannels = 5;

struct CandidateBuffer
{
  std::vector<float> x, y, z;
  std::array<std::vector<float>, kMaxChannels> channel;
  std::vector<std::uint32_t> hits; // buffer positions of the candidates inside the kernel radius
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
    for (auto* a : { &x, &y, &z, &distanceSquared })
    {
      a->resize(capacity);
    }
    hits.resize(capacity);
    for (int k = 0; k < channels; ++k)
    {
      channel[k].resize(capacity);
    }
    float lo[3], hi[3];
    grid.cellBox(ix, iy, iz, lo, hi);
    const float reach2 = reach * reach;
    size = 0;
    auto append = [&](std::uint32_t b, std::uint32_t e, const float shift[3])
    {
      for (std::uint32_t j = b; j < e; ++j)
      {
        const float px = s.x[j] + shift[0], py = s.y[j] + shift[1], pz = s.z[j] + shift[2];
        const float dx = std::max({ lo[0] - px, 0.0f, px - hi[0] });
        const float dy = std::max({ lo[1] - py, 0.0f, py - hi[1] });
        const float dz = std::max({ lo[2] - pz, 0.0f, pz - hi[2] });
        if (dx * dx + dy * dy + dz * dz >= reach2)
        {
          continue;
        }
        x[size] = px;
        y[size] = py;
        z[size] = pz;
        for (int k = 0; k < channels; ++k)
        {
          channel[k][size] = sources[k][j];
        }
        ++size;
      }
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
  std::uint32_t findHits(const float q[3], float h2)
  {
    return findHitsKernel(x.data(), y.data(), z.data(), size, q, h2, distanceSquared.data(), hits.data());
  }
};

/// Runs body(candidates, i) for every particle i, cell by cell in parallel, after gathering into a
/// thread-private buffer the candidates of that cell with the given per-particle channels. Each
/// particle is handled by one thread in a fixed candidate order, so results do not depend on the
/// thread count.
template<class Body>
void forEachParticleByCell(const NeighbourGrid& grid, const ParticleState& s, float reach, int threads,
                           std::initializer_list<const float*> channelSources, Body&& body)
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
      if (begin == end)
      {
        continue;
      }
      int ix, iy, iz;
      grid.cellCoordinates(static_cast<std::size_t>(c), ix, iy, iz);
      candidates.gather(grid, ix, iy, iz, s, reach, sources, channels);
      for (std::uint32_t i = begin; i < end; ++i)
      {
        body(candidates, i);
      }
    }
  }
}

} // namespace parafluid::sph::detail
