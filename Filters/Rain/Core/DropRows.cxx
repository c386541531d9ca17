#include "private/DropRows.h"

#include <cmath>

namespace parafluid::rain::detail
{
// Compiled for AVX-512, AVX2 and the baseline, chosen at load time (GCC's function multi-versioning).
#define PARAFLUID_DROP_ROWS_CLONES __attribute__((target_clones("arch=skylake-avx512", "avx2", "default")))

PARAFLUID_DROP_ROWS_CLONES
void evaluateRows(const DropRows& rows, std::int64_t begin, std::int64_t end, double t, bool terminal, double gravity,
                  double duration, float level, float* __restrict position, float* __restrict velocity,
                  std::uint8_t* __restrict inAir)
{
  const double* __restrict birthTime = rows.birth;
  const float* __restrict targetX = rows.targetX;
  const float* __restrict targetY = rows.targetY;
  const float* __restrict ground = rows.ground;
  const float* __restrict horizontalX = rows.horizontalX;
  const float* __restrict horizontalY = rows.horizontalY;
  const float* __restrict period = rows.period;
  const float* __restrict speed = rows.speed;
  const double g = terminal ? 0.0 : gravity; // ballistic drops accelerate; terminal ones do not
  const bool forever = duration <= 0.0;
  for (std::int64_t i = begin; i < end; ++i)
  {
    const double p = period[i];
    const double birth = birthTime[i];
    const double s = t - birth, remaining = p - s;
    const double v = speed[i];
    const double z = ground[i] + v * remaining + 0.5 * g * (p * p - s * s);
    position[3 * i] = static_cast<float>(targetX[i] - horizontalX[i] * remaining);
    position[3 * i + 1] = static_cast<float>(targetY[i] - horizontalY[i] * remaining);
    position[3 * i + 2] = static_cast<float>(z);
    velocity[3 * i] = horizontalX[i];
    velocity[3 * i + 1] = horizontalY[i];
    velocity[3 * i + 2] = static_cast<float>(-(v + g * s));
    // Above its target's ground until it gets there (over a ridge on its way it is hidden behind
    // the ground anyway); it falls into its own cell, where the water stops it.
    inAir[i] = static_cast<std::uint8_t>((forever | (birth <= duration)) & (z > level));
  }
}

PARAFLUID_DROP_ROWS_CLONES
void changedDrops(const float* __restrict phase, const double* __restrict inversePeriod, const double* __restrict drop,
                  std::int64_t begin, std::int64_t end, double t, std::uint8_t* __restrict changed)
{
  for (std::int64_t i = begin; i < end; ++i)
  {
    changed[i] = std::floor((t + phase[i]) * inversePeriod[i]) != drop[i] ? 1 : 0;
  }
}

PARAFLUID_DROP_ROWS_CLONES
void impactCandidates(const float* __restrict phase, const double* __restrict inversePeriod,
                      const std::int64_t* __restrict lastCounted, std::int64_t begin, std::int64_t end, double t,
                      bool wet, std::uint8_t* __restrict candidate)
{
  for (std::int64_t i = begin; i < end; ++i)
  {
    const double newest = std::floor((t + phase[i]) * inversePeriod[i]);
    candidate[i] = static_cast<std::uint8_t>((newest > static_cast<double>(lastCounted[i]) + 1.0) | wet);
  }
}
} // namespace parafluid::rain::detail
