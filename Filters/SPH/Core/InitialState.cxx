// The checks and completions of an initial particle state that every SPH backend runs before it
// starts (see InitialState.h).
#include "parafluid/sph/InitialState.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

namespace parafluid::sph
{
void completeInitialState(ParticleState& state)
{
  const std::size_t n = state.x.size();
  if (state.y.size() != n || state.z.size() != n)
  {
    throw std::invalid_argument("SPH: position arrays have different lengths");
  }
  const bool hasVelocity = state.vx.size() == n && state.vy.size() == n && state.vz.size() == n;
  const bool hasId = state.id.size() == n;
  const bool hasIndex = state.originalIndex.size() == n;
  if (!hasVelocity && !(state.vx.empty() && state.vy.empty() && state.vz.empty()))
  {
    throw std::invalid_argument("SPH: velocity arrays do not match the particle count");
  }
  std::vector<std::int64_t> ids;
  std::vector<std::uint32_t> indices;
  if (hasId)
  {
    ids.swap(state.id);
  }
  if (hasIndex)
  {
    indices.swap(state.originalIndex);
  }
  state.resize(n); // zero velocity when none was given; ids and indices default to the index
  if (hasId)
  {
    state.id.swap(ids);
  }
  if (hasIndex)
  {
    state.originalIndex.swap(indices);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const float s = state.x[i] + state.y[i] + state.z[i] + state.vx[i] + state.vy[i] + state.vz[i];
    if (!std::isfinite(s))
    {
      throw std::invalid_argument("SPH: particle " + std::to_string(i) + " (id " + std::to_string(state.id[i]) +
                                  ") has a NaN or infinite position or velocity");
    }
  }
}

double sceneSpeedLimit(const SPHParameters& p, const ParticleState& s)
{
  // The scene's own speed scale: free fall over the domain's largest extent, and the fastest
  // particle at the start.
  double extent = 0.0, g = 0.0, v0 = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent = std::max(extent, static_cast<double>(p.domainBounds[2 * a + 1] - p.domainBounds[2 * a]));
    g += static_cast<double>(p.gravity[a]) * p.gravity[a];
  }
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    v0 = std::max(v0, std::sqrt(static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
                                static_cast<double>(s.vz[i]) * s.vz[i]));
  }
  // 1 m/s floor: a weightless scene at rest may still start to move (surface tension).
  return 10.0 * (std::sqrt(2.0 * std::sqrt(g) * extent) + v0) + 1.0;
}

void checkCoincident(const ParticleState& s)
{
  std::vector<std::uint32_t> order(s.size());
  std::iota(order.begin(), order.end(), 0u);
  auto key = [&](std::uint32_t i) { return std::make_tuple(s.x[i], s.y[i], s.z[i]); };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::size_t shared = 0;
  std::uint32_t first = 0, second = 0;
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    if (key(order[k]) == key(order[k - 1]) && shared++ == 0)
    {
      first = std::min(order[k], order[k - 1]);
      second = std::max(order[k], order[k - 1]);
    }
  }
  if (shared > 0)
  {
    throw std::invalid_argument(
      "SPH: " + std::to_string(shared) + " particles share their position with another (first: particles " +
      std::to_string(first) + " and " + std::to_string(second) + " at (" + std::to_string(s.x[first]) + ", " +
      std::to_string(s.y[first]) + ", " + std::to_string(s.z[first]) +
      ")); SPH forces vanish at zero distance, so they would never separate: remove the duplicates upstream (the "
      "Clean filter) or move them apart");
  }
}

std::size_t appendParticles(ParticleState& s, const std::vector<float>& x, const std::vector<float>& y,
                            const std::vector<float>& z, const std::vector<float>& vx, const std::vector<float>& vy,
                            const std::vector<float>& vz, float restDensity)
{
  const std::size_t added = x.size();
  if (y.size() != added || z.size() != added || vx.size() != added || vy.size() != added || vz.size() != added)
  {
    throw std::invalid_argument("SPH: the added particles' arrays have different lengths");
  }
  for (std::size_t i = 0; i < added; ++i)
  {
    if (!std::isfinite(x[i] + y[i] + z[i] + vx[i] + vy[i] + vz[i]))
    {
      throw std::invalid_argument("SPH: added particle " + std::to_string(i) +
                                  " has a NaN or infinite position or velocity");
    }
  }
  if (added == 0)
  {
    return 0;
  }
  const std::size_t n = s.size();
  std::int64_t nextId = 0;
  std::uint32_t nextIndex = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    nextId = std::max(nextId, s.id[i] + 1);
    nextIndex = std::max(nextIndex, s.originalIndex[i] + 1);
  }
  s.x.insert(s.x.end(), x.begin(), x.end());
  s.y.insert(s.y.end(), y.begin(), y.end());
  s.z.insert(s.z.end(), z.begin(), z.end());
  s.vx.insert(s.vx.end(), vx.begin(), vx.end());
  s.vy.insert(s.vy.end(), vy.begin(), vy.end());
  s.vz.insert(s.vz.end(), vz.begin(), vz.end());
  for (auto* a : { &s.ax, &s.ay, &s.az, &s.pressure })
  {
    a->resize(n + added, 0.0f);
  }
  s.density.resize(n + added, restDensity);
  for (std::size_t i = 0; i < added; ++i)
  {
    s.id.push_back(nextId + static_cast<std::int64_t>(i));
    s.originalIndex.push_back(nextIndex + static_cast<std::uint32_t>(i));
  }
  return added;
}
} // namespace parafluid::sph
