#include "parafluid/rain/RainField.h"

#include "private/DropRandom.h"
#include "private/DropRows.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace parafluid::rain
{
namespace
{
enum Stream : std::uint64_t
{
  SizeStream = 1,
  TargetStream = 2,
  JitterStream = 3,
};

/// Smallest u in [0, 1] where the quadratic through f(0) = f0, f(1/2) = fm, f(1) = f1 reaches zero
/// from above (f0 > 0), or -1 when it stays positive.
double firstRoot(double f0, double fm, double f1)
{
  const double a = 2.0 * f1 - 4.0 * fm + 2.0 * f0, b = 4.0 * fm - f1 - 3.0 * f0, c = f0;
  double roots[2];
  int count = 0;
  if (std::fabs(a) < 1e-12 * (std::fabs(b) + std::fabs(c)))
  {
    if (b != 0.0)
    {
      roots[count++] = -c / b;
    }
  }
  else
  {
    const double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0)
    {
      // The stable pair of formulas (no cancellation).
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      roots[count++] = q / a;
      if (q != 0.0)
      {
        roots[count++] = c / q;
      }
    }
  }
  double best = -1.0;
  for (int r = 0; r < count; ++r)
  {
    if (roots[r] >= 0.0 && roots[r] <= 1.0 && (best < 0.0 || roots[r] < best))
    {
      best = roots[r];
    }
  }
  return best;
}

/// The lowest height of the bilinear ground over the rectangle [x0, x1] x [y0, y1]: it lies at a
/// corner, where an edge crosses a grid line, or on a grid node inside (a bilinear patch has no
/// interior minimum).
double lowestGround(const HeightField& ground, double x0, double x1, double y0, double y1)
{
  double origin[2], spacing[2];
  ground.grid(origin, spacing);
  auto lines = [](double a, double b, double o, double h, int nodes)
  {
    std::vector<double> at{ a, b };
    const auto first = static_cast<int>(std::clamp(std::ceil((a - o) / h), 0.0, 1.0 * nodes));
    const auto last = static_cast<int>(std::clamp(std::floor((b - o) / h), -1.0, nodes - 1.0));
    for (int i = first; i <= last; ++i)
    {
      at.push_back(o + i * h);
    }
    return at;
  };
  const auto xs = lines(x0, x1, origin[0], spacing[0], ground.nodesX());
  const auto ys = lines(y0, y1, origin[1], spacing[1], ground.nodesY());
  double lowest = std::numeric_limits<double>::infinity();
  for (double y : ys)
  {
    for (double x : xs)
    {
      lowest = std::min(lowest, ground.heightAt(x, y));
    }
  }
  return lowest;
}
} // namespace

RainField::RainField(const RainParameters& parameters, std::shared_ptr<const HeightField> ground)
  : Parameters(parameters)
  , Ground(std::move(ground))
  , Sizes(parameters.rainfallRate > 0.0 && parameters.rainfallRate <= 1e4 ? parameters.rainfallRate : 1.0)
{
  const std::string problem = this->Parameters.validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("Rain: " + problem);
  }
  if (!this->Ground)
  {
    throw std::invalid_argument("Rain: no ground (Terrain) to fall on");
  }
  const RainParameters& p = this->Parameters;
  const int nx = p.cells[0], ny = p.cells[1];
  this->CellSize[0] = (p.bounds[1] - p.bounds[0]) / nx;
  this->CellSize[1] = (p.bounds[3] - p.bounds[2]) / ny;
  const std::size_t cells = static_cast<std::size_t>(nx) * ny;
  // The air column over each cell, down to its lowest ground.
  std::vector<double> column(cells);
  double highestGround = -std::numeric_limits<double>::infinity();
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const double x0 = p.bounds[0] + i * this->CellSize[0], y0 = p.bounds[2] + j * this->CellSize[1];
      const double low = lowestGround(*this->Ground, x0, x0 + this->CellSize[0], y0, y0 + this->CellSize[1]);
      column[static_cast<std::size_t>(j) * nx + i] = p.height - low;
      this->CellLowest.push_back(low);
      highestGround = std::max(highestGround, low);
    }
  }
  const double shallowest = *std::min_element(column.begin(), column.end());
  if (!(shallowest > 0.0))
  {
    throw std::invalid_argument("Rain: PrecipitationHeight (" + std::to_string(p.height) +
                                " m) must be above the ground under the whole precipitation area (its lowest point "
                                "in one cell is at " +
                                std::to_string(p.height - shallowest) + " m)");
  }
  // Drops per cell: the drawn share of the real drops in its air column, rounded by largest
  // remainders (so the total is right), at least one per cell.
  const double perVolume = this->Sizes.dropsPerVolume() * p.dropsPerRealDrop * this->cellArea();
  std::vector<double> want(cells);
  std::vector<std::int64_t> count(cells);
  double total = 0.0;
  std::int64_t assigned = 0;
  for (std::size_t c = 0; c < cells; ++c)
  {
    want[c] = perVolume * column[c];
    total += want[c];
    count[c] = static_cast<std::int64_t>(std::floor(want[c]));
    assigned += count[c];
  }
  if (total > 2e8)
  {
    throw std::invalid_argument("Rain: " + std::to_string(total) +
                                " drops would be drawn (over 200 million): lower DropsPerRealDrop");
  }
  std::vector<std::uint32_t> order(cells);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b)
                   { return want[a] - std::floor(want[a]) > want[b] - std::floor(want[b]); });
  const auto remaining = std::max<std::int64_t>(0, std::llround(total) - assigned);
  for (std::int64_t r = 0; r < remaining && r < static_cast<std::int64_t>(cells); ++r)
  {
    ++count[order[r]];
  }
  std::int64_t slots = 0;
  for (auto& n : count)
  {
    n = std::max<std::int64_t>(n, 1);
    slots += n;
  }
  this->Cell.resize(slots);
  this->Diameter.resize(slots);
  this->Speed.resize(slots);
  this->Period.resize(slots);
  this->Phase.resize(slots);
  this->InversePeriod.resize(slots);
  this->CellWater.assign(cells, 0.0);
  this->CellStart.assign(cells + 1, 0);
  std::size_t s = 0;
  for (std::size_t c = 0; c < cells; ++c)
  {
    this->CellStart[c] = static_cast<std::int64_t>(s);
    double waterRate = 0.0; // sum of vol(D) / P over the cell's slots [m^3/s per real drop]
    for (std::int64_t k = 0; k < count[c]; ++k, ++s)
    {
      double u, v;
      detail::uniformPair(p.seed, s, 0, SizeStream, u, v);
      const double d = this->Sizes.diameterAt(u);
      const double speed = p.terminalVelocity ? DropSizeDistribution::terminalSpeed(d) : p.initialSpeed;
      const double h = column[c];
      const double period =
        p.terminalVelocity ? h / speed : (-speed + std::sqrt(speed * speed + 2.0 * p.gravity * h)) / p.gravity;
      this->Cell[s] = static_cast<std::uint32_t>(c);
      this->Diameter[s] = static_cast<float>(d);
      this->Speed[s] = static_cast<float>(speed);
      this->Period[s] = static_cast<float>(period);
      this->Phase[s] = static_cast<float>(v * period);
      this->InversePeriod[s] = 1.0 / static_cast<double>(this->Period[s]);
      waterRate += DropSizeDistribution::volume(this->Diameter[s]) / this->Period[s];
    }
    this->CellWater[c] = this->Sizes.rate() * this->cellArea() / waterRate;
  }
  this->CellStart[cells] = static_cast<std::int64_t>(s);
}

std::uint32_t RainField::cellOf(double x, double y) const
{
  const RainParameters& p = this->Parameters;
  const int i = std::clamp(static_cast<int>(std::floor((x - p.bounds[0]) / this->CellSize[0])), 0, p.cells[0] - 1);
  const int j = std::clamp(static_cast<int>(std::floor((y - p.bounds[2]) / this->CellSize[1])), 0, p.cells[1] - 1);
  return static_cast<std::uint32_t>(j * p.cells[0] + i);
}

double RainField::waterPerImpact(std::uint32_t slot) const
{
  return this->CellWater[this->Cell[slot]] * DropSizeDistribution::volume(this->Diameter[slot]);
}

bool RainField::born(std::uint32_t slot, std::int64_t k) const
{
  const double duration = this->Parameters.duration;
  return duration <= 0.0 || static_cast<double>(k) * this->Period[slot] - this->Phase[slot] <= duration;
}

bool RainField::mayBeUnderWater(std::uint32_t slot, const std::vector<float>* water) const
{
  // A drop lands in its own cell: water can stop it early only where it stands above that cell's
  // lowest ground.
  const std::uint32_t c = this->Cell[slot];
  return water && (*water)[c] > this->CellLowest[c];
}

std::int64_t RainField::dropAt(std::uint32_t slot, double t) const
{
  return static_cast<std::int64_t>(std::floor((t + this->Phase[slot]) * this->InversePeriod[slot]));
}

RainField::DropPath RainField::path(std::uint32_t slot, std::int64_t k) const
{
  const RainParameters& p = this->Parameters;
  const std::uint32_t c = this->Cell[slot];
  const int i = static_cast<int>(c % static_cast<std::uint32_t>(p.cells[0]));
  const int j = static_cast<int>(c / static_cast<std::uint32_t>(p.cells[0]));
  double u, v, a, b;
  detail::uniformPair(p.seed, slot, static_cast<std::uint64_t>(k), TargetStream, u, v);
  detail::uniformPair(p.seed, slot, static_cast<std::uint64_t>(k), JitterStream, a, b);
  DropPath path;
  path.target[0] = p.bounds[0] + (i + u) * this->CellSize[0];
  path.target[1] = p.bounds[2] + (j + v) * this->CellSize[1];
  path.ground = this->Ground->heightAt(path.target[0], path.target[1]);
  path.horizontal[0] = p.wind[0] + p.velocityJitter * (2.0 * a - 1.0);
  path.horizontal[1] = p.wind[1] + p.velocityJitter * (2.0 * b - 1.0);
  path.birth = static_cast<double>(k) * this->Period[slot] - this->Phase[slot];
  return path;
}

double RainField::heightAbove(std::uint32_t slot, double remaining) const
{
  const double v = this->Speed[slot];
  if (this->Parameters.terminalVelocity)
  {
    return v * remaining;
  }
  // Ballistic: z(s) = z0 - v s - g s^2 / 2 reaches the ground at s = P.
  const double period = this->Period[slot], s = period - remaining;
  return v * remaining + 0.5 * this->Parameters.gravity * (period * period - s * s);
}

double RainField::verticalSpeed(std::uint32_t slot, double s) const
{
  return this->Parameters.terminalVelocity ? -this->Speed[slot] : -(this->Speed[slot] + this->Parameters.gravity * s);
}

void RainField::evaluate(double t, const std::vector<float>* water, float* position, float* velocity,
                         std::uint8_t* inAir) const
{
  const auto n = static_cast<std::int64_t>(this->dropCount());
  DropCache& cache = this->Cache;
  if (cache.drop.size() != static_cast<std::size_t>(n))
  {
    cache.drop.assign(static_cast<std::size_t>(n), -1e300);
    cache.birth.assign(static_cast<std::size_t>(n), 0.0);
    for (auto* a : { &cache.targetX, &cache.targetY, &cache.ground, &cache.horizontalX, &cache.horizontalY })
    {
      a->assign(static_cast<std::size_t>(n), 0.0f);
    }
  }
  // Pass 1: the drop in each slot now; a slot whose drop changed since the last call gets its new
  // path (a drop lives for seconds, a frame is a few milliseconds: rare).
  std::vector<std::uint8_t>& changed = cache.changed;
  changed.resize(static_cast<std::size_t>(n));
#pragma omp parallel
  {
    const int part = omp_get_thread_num(), parts = omp_get_num_threads();
    const std::int64_t begin = n * part / parts, end = n * (part + 1) / parts;
    detail::changedDrops(this->Phase.data(), this->InversePeriod.data(), cache.drop.data(), begin, end, t,
                         changed.data());
    for (std::int64_t i = begin; i < end; ++i)
    {
      if (changed[i])
      {
        const auto slot = static_cast<std::uint32_t>(i);
        const std::int64_t k = this->dropAt(slot, t);
        const DropPath d = this->path(slot, k);
        cache.drop[i] = static_cast<double>(k);
        cache.birth[i] = d.birth;
        cache.targetX[i] = static_cast<float>(d.target[0]), cache.targetY[i] = static_cast<float>(d.target[1]);
        cache.ground[i] = static_cast<float>(d.ground);
        cache.horizontalX[i] = static_cast<float>(d.horizontal[0]);
        cache.horizontalY[i] = static_cast<float>(d.horizontal[1]);
      }
    }
  }
  // Pass 2: positions, velocities and whether in the air, a loop without calls (vectorised), over
  // each cell's slots with its water level.
  // Every output is written (a loop without branches vectorises): scratch for those not asked for.
  if (!position)
  {
    cache.position.resize(3 * static_cast<std::size_t>(n));
    position = cache.position.data();
  }
  if (!velocity)
  {
    cache.velocity.resize(3 * static_cast<std::size_t>(n));
    velocity = cache.velocity.data();
  }
  if (!inAir)
  {
    cache.inAir.resize(static_cast<std::size_t>(n));
    inAir = cache.inAir.data();
  }
  detail::DropRows rows;
  rows.birth = cache.birth.data(), rows.targetX = cache.targetX.data(), rows.targetY = cache.targetY.data();
  rows.ground = cache.ground.data(), rows.horizontalX = cache.horizontalX.data();
  rows.horizontalY = cache.horizontalY.data(), rows.period = this->Period.data(), rows.speed = this->Speed.data();
  const int cells = this->cellCount();
#pragma omp parallel for schedule(static)
  for (int c = 0; c < cells; ++c)
  {
    const float level = water ? (*water)[c] : -std::numeric_limits<float>::max();
    detail::evaluateRows(rows, this->CellStart[c], this->CellStart[c + 1], t, this->Parameters.terminalVelocity,
                         this->Parameters.gravity, this->Parameters.duration, level, position, velocity, inAir);
  }
}

void RainField::drop(std::uint32_t slot, double t, double position[3], double velocity[3]) const
{
  const DropPath d = this->path(slot, this->dropAt(slot, t));
  const double s = t - d.birth, remaining = this->Period[slot] - s;
  position[0] = d.target[0] - d.horizontal[0] * remaining;
  position[1] = d.target[1] - d.horizontal[1] * remaining;
  position[2] = d.ground + this->heightAbove(slot, remaining);
  velocity[0] = d.horizontal[0], velocity[1] = d.horizontal[1], velocity[2] = this->verticalSpeed(slot, s);
}

Impact RainField::impactOf(std::uint32_t slot, std::int64_t k, const std::vector<float>* water) const
{
  const DropPath d = this->path(slot, k);
  const double period = this->Period[slot];
  const HeightField& ground = *this->Ground;
  // f(s) = drop height - ground height along the path, s = time since birth in [0, P]. Between
  // grid lines the bilinear ground is quadratic along a straight path and the drop's height is at
  // most quadratic, so f is a quadratic on each piece: three samples give it exactly.
  auto position = [&](double s, double& x, double& y)
  {
    x = d.target[0] - d.horizontal[0] * (period - s);
    y = d.target[1] - d.horizontal[1] * (period - s);
  };
  auto f = [&](double s)
  {
    double x, y;
    position(s, x, y);
    return d.ground + this->heightAbove(slot, period - s) - ground.heightAt(x, y);
  };
  double hit = period;
  const double speed = std::hypot(d.horizontal[0], d.horizontal[1]);
  if (speed > 0.0)
  {
    // Where the path crosses grid lines (inside the grid; beyond it the ground is held constant).
    double origin[2], spacing[2];
    ground.grid(origin, spacing);
    const int nodes[2] = { ground.nodesX(), ground.nodesY() };
    std::vector<double> breaks{ 0.0, period };
    for (int a = 0; a < 2; ++a)
    {
      if (d.horizontal[a] == 0.0)
      {
        continue;
      }
      const double start = d.target[a] - d.horizontal[a] * period, end = d.target[a];
      const double lo = std::min(start, end), hi = std::max(start, end);
      const auto first = static_cast<int>(std::clamp(std::ceil((lo - origin[a]) / spacing[a]), 0.0, 1.0 * nodes[a]));
      const auto last = static_cast<int>(std::clamp(std::floor((hi - origin[a]) / spacing[a]), -1.0, nodes[a] - 1.0));
      for (int line = first; line <= last; ++line)
      {
        const double s = (origin[a] + line * spacing[a] - start) / d.horizontal[a];
        if (s > 0.0 && s < period)
        {
          breaks.push_back(s);
        }
      }
    }
    std::sort(breaks.begin(), breaks.end());
    for (std::size_t b = 0; b + 1 < breaks.size(); ++b)
    {
      const double sa = breaks[b], sb = breaks[b + 1];
      if (sb - sa <= 0.0)
      {
        continue;
      }
      const double f0 = f(sa);
      if (f0 <= 0.0)
      {
        hit = sa;
        break;
      }
      const double u = firstRoot(f0, f(0.5 * (sa + sb)), f(sb));
      if (u >= 0.0)
      {
        // On the last piece the target itself is a root (u = 1): then the drop gets there.
        if (sb < period || u < 1.0 - 1e-9)
        {
          hit = sa + u * (sb - sa);
        }
        break;
      }
    }
  }
  Impact impact;
  impact.slot = slot;
  impact.drop = k;
  double x, y;
  position(hit, x, y);
  double z = ground.heightAt(x, y);
  // The water of the cell the drop falls into, when it stands above the ground there.
  const std::uint32_t cell = this->cellOf(x, y);
  if (water && (*water)[cell] > z)
  {
    const double level = (*water)[cell];
    // Solve height above the target = level - target ground for the remaining time (monotone).
    double lo = 0.0, hi = period - 0.0;
    const double want = level - d.ground;
    if (this->heightAbove(slot, period) <= want)
    {
      hit = 0.0;
    }
    else
    {
      for (int it = 0; it < 60; ++it)
      {
        const double mid = 0.5 * (lo + hi); // remaining time
        (this->heightAbove(slot, mid) > want ? hi : lo) = mid;
      }
      hit = std::min(hit, period - hi);
    }
    position(hit, x, y);
    z = level;
    impact.onWater = true;
  }
  impact.cell = this->cellOf(x, y);
  impact.time = d.birth + hit;
  impact.position[0] = static_cast<float>(x), impact.position[1] = static_cast<float>(y);
  impact.position[2] = static_cast<float>(z);
  impact.velocity[0] = static_cast<float>(d.horizontal[0]), impact.velocity[1] = static_cast<float>(d.horizontal[1]);
  impact.velocity[2] = static_cast<float>(this->verticalSpeed(slot, hit));
  return impact;
}

void RainField::collectImpacts(double t, const std::vector<float>* water, std::vector<std::int64_t>& lastCounted,
                               std::vector<Impact>& impacts) const
{
  const std::size_t n = this->dropCount();
  if (lastCounted.size() != n)
  {
    // Nothing counted yet: the drops in the air at the start are the first to count.
    lastCounted.resize(n);
    for (std::size_t s = 0; s < n; ++s)
    {
      lastCounted[s] = this->dropAt(static_cast<std::uint32_t>(s), 0.0) - 1;
    }
  }
  // Which slots may have something to count (a vectorised pass over each cell's slots, which lie
  // together), then those slots in parallel, gathered in slot order (the same list for any thread
  // count).
  std::vector<std::uint8_t>& candidate = this->Cache.candidate;
  candidate.resize(n);
  const int cells = this->cellCount();
#pragma omp parallel for schedule(static)
  for (int c = 0; c < cells; ++c)
  {
    const std::int64_t begin = this->CellStart[c], end = this->CellStart[c + 1];
    const bool wet = water && (*water)[c] > this->CellLowest[c];
    detail::impactCandidates(this->Phase.data(), this->InversePeriod.data(), lastCounted.data(), begin, end, t, wet,
                             candidate.data());
  }
  const int threads = 64;
  std::vector<std::vector<Impact>> found(threads);
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
  for (int part = 0; part < threads; ++part)
  {
    const std::int64_t begin = count * part / threads, end = count * (part + 1) / threads;
    for (std::int64_t i = begin; i < end; ++i)
    {
      if (!candidate[i])
      {
        continue;
      }
      const auto slot = static_cast<std::uint32_t>(i);
      const std::int64_t newest = this->dropAt(slot, t);
      for (std::int64_t k = lastCounted[i] + 1; k <= newest; ++k)
      {
        // Drop k meets the ground by the birth of k + 1; it may meet the water earlier.
        if (!this->born(slot, k))
        {
          lastCounted[i] = k; // after the shower: never falls
          continue;
        }
        if (k < newest || this->mayBeUnderWater(slot, water))
        {
          const Impact impact = this->impactOf(slot, k, water);
          if (impact.time <= t)
          {
            found[part].push_back(impact);
            lastCounted[i] = k;
            continue;
          }
        }
        break;
      }
    }
  }
  for (auto& list : found)
  {
    impacts.insert(impacts.end(), list.begin(), list.end());
  }
}

void RainField::recentImpacts(double t, double window, const std::vector<float>* water,
                              std::vector<Impact>& impacts) const
{
  const int threads = 64;
  std::vector<std::vector<Impact>> found(threads);
  const auto count = static_cast<std::int64_t>(this->dropCount());
#pragma omp parallel for schedule(static)
  for (int part = 0; part < threads; ++part)
  {
    const std::int64_t begin = count * part / threads, end = count * (part + 1) / threads;
    for (std::int64_t i = begin; i < end; ++i)
    {
      const auto slot = static_cast<std::uint32_t>(i);
      const std::int64_t newest = this->dropAt(slot, t);
      const std::int64_t oldest = this->dropAt(slot, t - window) - 1;
      for (std::int64_t k = std::max(oldest, newest - 64); k <= newest; ++k)
      {
        if (k == newest && !this->mayBeUnderWater(slot, water))
        {
          break; // the drop in the air meets the ground only when the next one is born
        }
        if (!this->born(slot, k))
        {
          break;
        }
        const Impact impact = this->impactOf(slot, k, water);
        if (impact.time <= t && impact.time > t - window)
        {
          found[part].push_back(impact);
        }
      }
    }
  }
  for (auto& list : found)
  {
    impacts.insert(impacts.end(), list.begin(), list.end());
  }
}
} // namespace parafluid::rain
