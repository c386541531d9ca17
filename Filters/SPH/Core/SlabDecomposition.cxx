#include "private/SlabDecomposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace parafluid::sph::detail
{
namespace
{
constexpr int kBins = 4096;

/// The smallest and largest value over every process (+inf, -inf when there is none).
std::pair<double, double> globalRange(const std::vector<float>& values, Communicator& communicator)
{
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (float v : values)
  {
    low = std::min(low, static_cast<double>(v));
    high = std::max(high, static_cast<double>(v));
  }
  std::vector<double> extremes = { -low, high };
  communicator.reduce(extremes, Reduction::Max);
  return { -extremes[0], extremes[1] };
}
} // namespace

SlabDecomposition::SlabDecomposition(const SPHParameters& p, const std::vector<float>* position[3],
                                     Communicator& communicator)
{
  double best = -1.0;
  bool bestAcross = false;
  for (int a = 0; a < 3; ++a)
  {
    const auto [low, high] = globalRange(*position[a], communicator);
    if (p.periodic[a])
    {
      continue;
    }
    // Across gravity a slab's columns stand whole, and the water's depth does not set its share.
    const bool across = p.gravity[a] == 0.0f;
    const double extent = high >= low ? high - low : 0.0;
    if (best < 0.0 || (across && !bestAcross) || (across == bestAcross && extent > best))
    {
      best = extent;
      bestAcross = across;
      this->Axis = a;
    }
  }
  if (best < 0.0)
  {
    throw std::invalid_argument("SPH: a distributed run cuts the domain along an axis that is not periodic; "
                                "every axis is periodic (turn one of PeriodicX, PeriodicY, PeriodicZ off)");
  }
  this->balance(*position[this->Axis], communicator);
}

void SlabDecomposition::balance(const std::vector<float>& coordinate, Communicator& communicator)
{
  const int size = communicator.size();
  const float infinity = std::numeric_limits<float>::infinity();
  this->Cuts.assign(static_cast<std::size_t>(size) + 1, infinity);
  this->Cuts[0] = -infinity;
  const auto [low, high] = globalRange(coordinate, communicator);
  std::vector<double> histogram(kBins, 0.0);
  const double width = high > low ? (high - low) / kBins : 1.0;
  for (float c : coordinate)
  {
    const auto bin = static_cast<int>((c - low) / width);
    histogram[static_cast<std::size_t>(std::clamp(bin, 0, kBins - 1))] += 1.0;
  }
  communicator.reduce(histogram, Reduction::Sum);
  double total = 0.0;
  for (double count : histogram)
  {
    total += count;
  }
  if (!(high >= low) || total == 0.0)
  {
    return; // no particles anywhere: everything (nothing) belongs to the first process
  }
  // Cut r lies at the upper edge of the bin where the running count first reaches r / size of the
  // total, so a slab is a whole number of bins.
  double running = 0.0;
  int next = 1;
  for (int bin = 0; bin < kBins && next < size; ++bin)
  {
    running += histogram[static_cast<std::size_t>(bin)];
    while (next < size && running >= total * next / size)
    {
      this->Cuts[static_cast<std::size_t>(next)] = static_cast<float>(low + (bin + 1) * width);
      ++next;
    }
  }
}

int SlabDecomposition::owner(float c) const
{
  // upper_bound: a particle on a cut belongs to the slab above it.
  const auto it = std::upper_bound(this->Cuts.begin() + 1, this->Cuts.end() - 1, c);
  return static_cast<int>(it - (this->Cuts.begin() + 1));
}

std::pair<int, int> SlabDecomposition::within(float c, float reach) const
{
  return { this->owner(c - reach), this->owner(c + reach) + 1 };
}
} // namespace parafluid::sph::detail
