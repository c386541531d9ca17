#include "private/DropRows.h"

#include "parafluid/common/SimdDispatch.h"

#include <cmath>

namespace parafluid::rain::detail
{
namespace
{

__attribute__((always_inline)) inline void evaluateRowsBody(const DropRows& rows, std::int64_t begin, std::int64_t end,
                                                            double t, bool terminal, double gravity, double duration,
                                                            float level, float* __restrict position,
                                                            float* __restrict velocity, std::uint8_t* __restrict inAir)
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

__attribute__((always_inline)) inline void changedDropsBody(const float* __restrict phase,
                                                            const double* __restrict inversePeriod,
                                                            const double* __restrict drop, std::int64_t begin,
                                                            std::int64_t end, double t,
                                                            std::uint8_t* __restrict changed)
{
  for (std::int64_t i = begin; i < end; ++i)
  {
    changed[i] = std::floor((t + phase[i]) * inversePeriod[i]) != drop[i] ? 1 : 0;
  }
}

__attribute__((always_inline)) inline void impactCandidatesBody(const float* __restrict phase,
                                                                const double* __restrict inversePeriod,
                                                                const std::int64_t* __restrict lastCounted,
                                                                std::int64_t begin, std::int64_t end, double t,
                                                                bool wet, std::uint8_t* __restrict candidate)
{
  for (std::int64_t i = begin; i < end; ++i)
  {
    const double newest = std::floor((t + phase[i]) * inversePeriod[i]);
    candidate[i] = static_cast<std::uint8_t>((newest > static_cast<double>(lastCounted[i]) + 1.0) | wet);
  }
}
} // namespace

// Each compiled for AVX-512, AVX2 and the baseline, the widest picked at run time.
PARAFLUID_SIMD_DISPATCH(evaluateRows,
                        (const DropRows& rows, std::int64_t begin, std::int64_t end, double t, bool terminal,
                         double gravity, double duration, float level, float* __restrict position,
                         float* __restrict velocity, std::uint8_t* __restrict inAir),
                        (rows, begin, end, t, terminal, gravity, duration, level, position, velocity, inAir),
                        evaluateRowsBody)

PARAFLUID_SIMD_DISPATCH(changedDrops,
                        (const float* __restrict phase, const double* __restrict inversePeriod,
                         const double* __restrict drop, std::int64_t begin, std::int64_t end, double t,
                         std::uint8_t* __restrict changed),
                        (phase, inversePeriod, drop, begin, end, t, changed), changedDropsBody)

PARAFLUID_SIMD_DISPATCH(impactCandidates,
                        (const float* __restrict phase, const double* __restrict inversePeriod,
                         const std::int64_t* __restrict lastCounted, std::int64_t begin, std::int64_t end, double t,
                         bool wet, std::uint8_t* __restrict candidate),
                        (phase, inversePeriod, lastCounted, begin, end, t, wet, candidate), impactCandidatesBody)
} // namespace parafluid::rain::detail
