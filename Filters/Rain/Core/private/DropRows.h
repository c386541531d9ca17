#pragma once
// The inner loop of RainField::evaluate: each drop's position, velocity and whether it is in the
// air, from its slot's constants and its cached path. A function of its own with restrict pointers
// and no calls, so that the compiler vectorises it.
#include <cstdint>

namespace parafluid::rain::detail
{
struct DropRows
{
  const double* birth;
  const float *targetX, *targetY, *ground, *horizontalX, *horizontalY;
  const float *period, *speed;
};

/// Rows [begin, end) all of one cell, whose water stands at `level` (lowest float: none); every
/// output is written.
void evaluateRows(const DropRows& rows, std::int64_t begin, std::int64_t end, double t, bool terminal, double gravity,
                  double duration, float level, float* __restrict position, float* __restrict velocity,
                  std::uint8_t* __restrict inAir);
/// changed[i] = 1 where the drop in slot i at time t is not `drop[i]` (its index as a double,
/// exact below 2^53; then its path needs refreshing), for i in [begin, end).
void changedDrops(const float* __restrict phase, const double* __restrict inversePeriod, const double* __restrict drop,
                  std::int64_t begin, std::int64_t end, double t, std::uint8_t* __restrict changed);

/// candidate[i] = 1 where slot i may have an impact to count by time t: a drop after the one in
/// the air now was born since lastCounted, or (wet) water may stop the drop in the air early.
void impactCandidates(const float* __restrict phase, const double* __restrict inversePeriod,
                      const std::int64_t* __restrict lastCounted, std::int64_t begin, std::int64_t end, double t,
                      bool wet, std::uint8_t* __restrict candidate);
} // namespace parafluid::rain::detail
