// SPH Step's optional output fields of a state in any order: a copy sorted by a CPU neighbour grid,
// the field computed there and returned in the state's order.
#include "parafluid/sph/OutputFields.h"

#include "private/NeighbourCandidates.h"
#include "private/OutputFields.h"

namespace parafluid::sph
{
namespace
{
/// field(grid, sorted copy) for a grid built over s, mapped back to s's order.
template<class T, class Field>
std::vector<T> inStateOrder(const SPHParameters& p, const ParticleState& s, Field&& field)
{
  NeighbourGrid grid;
  for (int a = 0; a < 3; ++a)
  {
    if (p.periodic[a])
    {
      grid.setPeriodic(a, p.domainBounds[2 * a], p.domainBounds[2 * a + 1]);
    }
  }
  grid.build(s.x.data(), s.y.data(), s.z.data(), s.size(), p.smoothingLength);
  const std::vector<std::uint32_t>& order = grid.sortedOrder();
  ParticleState sorted;
  for (auto [from, to] : { std::pair{ &s.x, &sorted.x },
                           { &s.y, &sorted.y },
                           { &s.z, &sorted.z },
                           { &s.density, &sorted.density },
                           { &s.pressure, &sorted.pressure } })
  {
    to->resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      (*to)[k] = (*from)[order[k]];
    }
  }
  const std::vector<T> values = field(grid, sorted);
  std::vector<T> out(values.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    out[order[k]] = values[k];
  }
  return out;
}
} // namespace

std::vector<float> smoothedPressure(const SPHParameters& p, const ParticleState& s)
{
  return inStateOrder<float>(p, s,
                             [&](const NeighbourGrid& g, const ParticleState& sorted)
                             { return detail::smoothedPressureOnGrid(g, sorted, p); });
}

std::vector<std::uint32_t> neighbourCounts(const SPHParameters& p, const ParticleState& s)
{
  return inStateOrder<std::uint32_t>(p, s,
                                     [&](const NeighbourGrid& g, const ParticleState& sorted)
                                     { return detail::neighbourCountsOnGrid(g, sorted, p); });
}
} // namespace parafluid::sph
