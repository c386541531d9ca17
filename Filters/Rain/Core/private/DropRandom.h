#pragma once
// Counter-based random numbers: a drop's numbers are a hash of (seed, slot, drop, stream), so any
// drop at any time is drawn without a generator's state, identically on any thread.
#include <cstdint>

namespace parafluid::rain::detail
{
inline std::uint64_t splitMix(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// Two uniform numbers in [0, 1) with 32 bits each.
inline void uniformPair(std::uint64_t seed, std::uint64_t slot, std::uint64_t drop, std::uint64_t stream, double& u,
                        double& v)
{
  const std::uint64_t h = splitMix(splitMix(splitMix(seed ^ (stream << 56)) ^ slot) ^ static_cast<std::uint64_t>(drop));
  u = static_cast<double>(h >> 32) * (1.0 / 4294967296.0);
  v = static_cast<double>(h & 0xFFFFFFFFULL) * (1.0 / 4294967296.0);
}
} // namespace parafluid::rain::detail
