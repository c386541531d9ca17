#include "parafluid/terrain/DropletErosion.h"

#include "parafluid/terrain/TerrainParameterTables.h"

#include "parafluid/terrain/PerlinNoise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace parafluid::terrain
{
std::string DropletSettings::problem() const
{
  return checkDeclared(dropletParameterTable(), *this);
}

namespace
{
/// One step of a drop: the cell it stood in, where in it, and what it did there: amount > 0
/// deposited (bilinearly on the cell's corners), < 0 eroded (under the brush at the nearest
/// node), 0 only passed.
struct DropEvent
{
  std::uint32_t i, j;
  float fx, fy;
  float nextX, nextY; // where the step went (in cells)
  float amount;
  bool uphill; // a deposit that fills a pit (limited by the rise it fills)
};

/// Erosion brush: the nodes within `radius` of a centre, weighted by radius - distance.
/// Away from the edges (reach nodes or more) the whole brush is inside the grid: its nodes are
/// fixed offsets in the array and its normalised weights fixed too.
struct Brush
{
  std::vector<int> di, dj;
  std::vector<float> weight;
  int reach = 0;
  std::vector<std::ptrdiff_t> offset; // dj * nx + di
  std::vector<float> share;           // weight / sum of weights
  Brush(float radius, int nx)
  {
    reach = static_cast<int>(std::ceil(radius));
    for (int b = -reach; b <= reach; ++b)
    {
      for (int a = -reach; a <= reach; ++a)
      {
        const float d = std::sqrt(static_cast<float>(a * a + b * b));
        if (d < radius)
        {
          di.push_back(a), dj.push_back(b), weight.push_back(radius - d);
        }
      }
    }
    float total = 0.0f;
    for (const float w : weight)
    {
      total += w;
    }
    for (std::size_t k = 0; k < weight.size(); ++k)
    {
      offset.push_back(static_cast<std::ptrdiff_t>(dj[k]) * nx + di[k]);
      share.push_back(weight[k] / total);
    }
  }
};

/// Height and gradient of the bilinear interpolant in cell (i, j) at fractions (fx, fy).
inline float sample(const std::vector<float>& h, int nx, int i, int j, float fx, float fy, float& gx, float& gy)
{
  const std::size_t k = static_cast<std::size_t>(j) * nx + i;
  const float h00 = h[k], h10 = h[k + 1], h01 = h[k + nx], h11 = h[k + nx + 1];
  gx = (h10 - h00) * (1.0f - fy) + (h11 - h01) * fy;
  gy = (h01 - h00) * (1.0f - fx) + (h11 - h10) * fx;
  // Written from h00 by differences, so flat ground gives exactly its height (no rounding slope).
  return h00 + fx * (h10 - h00) + fy * (h01 - h00) + fx * fy * (h00 - h10 - h01 + h11);
}

/// Height at (x, y) in cells, inside the grid.
inline float heightAt(const std::vector<float>& h, int nx, int ny, float x, float y)
{
  const int i = std::min(static_cast<int>(x), nx - 2), j = std::min(static_cast<int>(y), ny - 2);
  float gx, gy;
  return sample(h, nx, i, j, x - static_cast<float>(i), y - static_cast<float>(j), gx, gy);
}

/// Traces drop `index` on the snapshot h; returns the events written to `events`.
int traceDrop(const DropletSettings& s, const std::vector<float>& h, int nx, int ny, std::uint64_t key, long long index,
              DropEvent* events)
{
  std::uint64_t state = splitMix64(key ^ static_cast<std::uint64_t>(index));
  const auto uniform = [&state]()
  {
    state = splitMix64(state);
    return static_cast<float>(unitFromHash(state));
  };
  float x = uniform() * static_cast<float>(nx - 1), y = uniform() * static_cast<float>(ny - 1);
  float dirX = 0.0f, dirY = 0.0f, speed = 1.0f, water = 1.0f, sediment = 0.0f;
  int count = 0;
  const float xMax = static_cast<float>(nx - 1), yMax = static_cast<float>(ny - 1);
  for (int step = 0; step < s.maxSteps; ++step)
  {
    const int i = std::min(static_cast<int>(x), nx - 2), j = std::min(static_cast<int>(y), ny - 2);
    const float fx = x - static_cast<float>(i), fy = y - static_cast<float>(j);
    float gx, gy;
    const float height = sample(h, nx, i, j, fx, fy, gx, gy);
    dirX = dirX * s.inertia - gx * (1.0f - s.inertia);
    dirY = dirY * s.inertia - gy * (1.0f - s.inertia);
    float length = std::sqrt(dirX * dirX + dirY * dirY);
    if (!(length > 1e-12f))
    {
      // Flat ground: a random direction (from the drop's own stream).
      const float angle = 6.2831853f * uniform();
      dirX = std::cos(angle), dirY = std::sin(angle), length = 1.0f;
    }
    dirX /= length, dirY /= length;
    DropEvent& event = events[count++];
    const float nextX = x + dirX, nextY = y + dirY;
    event = { static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), fx, fy, nextX, nextY, 0.0f, false };
    if (!(nextX >= 0.0f && nextX < xMax && nextY >= 0.0f && nextY < yMax))
    {
      break; // off the grid: what it carries leaves with it
    }
    const int ni = std::min(static_cast<int>(nextX), nx - 2), nj = std::min(static_cast<int>(nextY), ny - 2);
    float ngx, ngy;
    const float dh =
      sample(h, nx, ni, nj, nextX - static_cast<float>(ni), nextY - static_cast<float>(nj), ngx, ngy) - height;
    const float capacity = std::max(-dh, s.minSlope) * speed * water * s.capacity;
    if (sediment > capacity || dh > 0.0f)
    {
      const float amount = dh > 0.0f ? std::min(dh, sediment) : (sediment - capacity) * s.depositRate;
      sediment -= amount;
      event.amount = amount;
      event.uphill = dh > 0.0f;
    }
    else
    {
      const float amount = std::min((capacity - sediment) * s.erodeRate, -dh);
      sediment += amount;
      event.amount = -amount;
    }
    speed = std::sqrt(std::max(0.0f, speed * speed - dh * s.gravity));
    water *= 1.0f - s.evaporation;
    x = nextX, y = nextY;
    if (!(water > 1e-6f))
    {
      break;
    }
  }
  return count;
}
} // namespace

SedimentBudget erodeWithDroplets(const DropletSettings& s, ElevationGrid& grid, ErosionMaps& maps,
                                 const std::function<bool(double)>& progress)
{
  std::string problem = s.problem();
  if (problem.empty())
  {
    problem = grid.problem();
  }
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  const int nx = grid.nx, ny = grid.ny;
  const std::size_t n = grid.size();
  maps.waterFlow.assign(n, 0.0f);
  maps.sedimentDeposited.assign(n, 0.0f);
  maps.erodedDepth.assign(n, 0.0f);
  SedimentBudget budget;
  // Heights in units of the grid spacing: the drop moves one spacing per step.
  const double unit = 0.5 * (grid.dx + grid.dy);
  const double cellArea = grid.dx * grid.dy;
  std::vector<float> h(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    h[k] = static_cast<float>(grid.elevation[k] / unit);
  }
  std::vector<float> erodedUnits(n, 0.0f), depositedUnits(n, 0.0f);
  const Brush brush(s.radius, nx);
  const std::uint64_t key = splitMix64(s.seed ^ 0x64726f70ull);
  // The events of a batch are held at once: long lifetimes get smaller batches, so the buffer stays
  // under 2^21 events (64 MB) whatever MaxLifetime is (a function of the settings only, so still
  // the same result on any thread count).
  const auto batch =
    std::min(static_cast<long long>(s.batchSize), std::max(16LL, static_cast<long long>((1 << 21) / s.maxSteps)));
  std::vector<DropEvent> events(static_cast<std::size_t>(batch) * static_cast<std::size_t>(s.maxSteps));
  std::vector<int> counts(static_cast<std::size_t>(batch));
  std::vector<float> brushWeights(brush.weight.size());
  for (long long first = 0; first < s.drops; first += batch)
  {
    const long long inBatch = std::min(batch, s.drops - first);
#pragma omp parallel for schedule(dynamic, 16)
    for (long long d = 0; d < inBatch; ++d)
    {
      counts[static_cast<std::size_t>(d)] = traceDrop(s, h, nx, ny, key, first + d, events.data() + d * s.maxSteps);
    }
    // Apply in drop order: the same sums in the same order on any thread count. Each amount is
    // limited again by the terrain as the earlier drops left it (the drops of a batch that
    // converge on one cell would otherwise each dig the full drop of the snapshot, and the next
    // batch would see a steeper pit: a runaway), and by what the drop carries then; the drop's
    // sediment is counted here, so the budget closes whatever the limits did.
    for (long long d = 0; d < inBatch; ++d)
    {
      const DropEvent* e = events.data() + d * s.maxSteps;
      float sediment = 0.0f;
      for (int k = 0; k < counts[static_cast<std::size_t>(d)]; ++k, ++e)
      {
        const std::size_t cell = static_cast<std::size_t>(e->j) * nx + e->i;
        maps.waterFlow[cell] += 1.0f;
        if (e->amount == 0.0f)
        {
          continue;
        }
        const float here = h[cell] + e->fx * (h[cell + 1] - h[cell]) + e->fy * (h[cell + nx] - h[cell]) +
                           e->fx * e->fy * (h[cell] - h[cell + 1] - h[cell + nx] + h[cell + nx + 1]);
        const float rise = heightAt(h, nx, ny, e->nextX, e->nextY) - here;
        if (e->amount > 0.0f)
        {
          const float amount = std::min(std::min(e->amount, sediment), e->uphill ? std::max(rise, 0.0f) : e->amount);
          if (!(amount > 0.0f))
          {
            continue;
          }
          sediment -= amount;
          const float w[4] = { (1 - e->fx) * (1 - e->fy), e->fx * (1 - e->fy), (1 - e->fx) * e->fy, e->fx * e->fy };
          const std::size_t corner[4] = { cell, cell + 1, cell + nx, cell + nx + 1 };
          for (int c = 0; c < 4; ++c)
          {
            h[corner[c]] += amount * w[c];
            depositedUnits[corner[c]] += amount * w[c];
          }
          budget.deposited += amount;
        }
        else
        {
          // The brush at the node nearest the drop, renormalised over the nodes inside the grid.
          const int ci = static_cast<int>(e->i) + (e->fx >= 0.5f ? 1 : 0);
          const int cj = static_cast<int>(e->j) + (e->fy >= 0.5f ? 1 : 0);
          const float amount = std::min(-e->amount, std::max(-rise, 0.0f));
          if (!(amount > 0.0f))
          {
            continue;
          }
          sediment += amount;
          budget.eroded += amount;
          if (ci >= brush.reach && ci < nx - brush.reach && cj >= brush.reach && cj < ny - brush.reach)
          {
            float* centre = h.data() + static_cast<std::size_t>(cj) * nx + ci;
            float* taken = erodedUnits.data() + static_cast<std::size_t>(cj) * nx + ci;
            for (std::size_t b = 0; b < brush.share.size(); ++b)
            {
              const float part = amount * brush.share[b];
              centre[brush.offset[b]] -= part;
              taken[brush.offset[b]] += part;
            }
            continue;
          }
          float total = 0.0f;
          for (std::size_t b = 0; b < brush.weight.size(); ++b)
          {
            const int a = ci + brush.di[b], c = cj + brush.dj[b];
            brushWeights[b] = (a >= 0 && a < nx && c >= 0 && c < ny) ? brush.weight[b] : 0.0f;
            total += brushWeights[b];
          }
          for (std::size_t b = 0; b < brush.weight.size(); ++b)
          {
            if (brushWeights[b] > 0.0f)
            {
              const std::size_t node = static_cast<std::size_t>(cj + brush.dj[b]) * nx + (ci + brush.di[b]);
              const float taken = amount * brushWeights[b] / total;
              h[node] -= taken;
              erodedUnits[node] += taken;
            }
          }
        }
      }
      budget.carried += sediment;
    }
    if (progress && !progress(static_cast<double>(first + inBatch) / static_cast<double>(s.drops)))
    {
      break;
    }
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    // As a change of the original, so ground no drop touched keeps its exact value.
    grid.elevation[k] += static_cast<float>((static_cast<double>(depositedUnits[k]) - erodedUnits[k]) * unit);
    maps.sedimentDeposited[k] = static_cast<float>(depositedUnits[k] * unit);
    maps.erodedDepth[k] = static_cast<float>(erodedUnits[k] * unit);
  }
  const double volume = unit * cellArea;
  budget.eroded *= volume, budget.deposited *= volume, budget.carried *= volume;
  return budget;
}
} // namespace parafluid::terrain
