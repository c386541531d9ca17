#pragma once
// The hot vector loops (trilinear row reads, the multigrid smoother, vorticity confinement, the
// drop rows, δ-SPH's pair loops and the neighbour search's hits) are compiled three times, for AVX-512, AVX2 and the
// baseline, and the widest this CPU runs is picked on the first call. Why not GCC's target_clones: its
// "arch=skylake-avx512" clone is chosen only when the CPU *is* a Skylake-SP (__builtin_cpu_is), so Ice Lake, Sapphire
// and Emerald Rapids servers ran the AVX2 copy; and under generic tuning Debian's GCC 12 emits no gather instructions
// (its fix for Intel's GDS, CVE-2022-40982), so the trilinear reads were eight scalar loads a lane. The AVX-512 copy
// here names its instruction sets and a tuning that gathers: on an Emerald Rapids core a trilinear read of a 64^3 grid
// takes 4-5 ns in it against 10-11 ns in the AVX2 copy.
//
// PARAFLUID_SIMD=avx2 or =baseline in the environment caps the choice (benchmarks compare the
// copies in one run; the tests check that they agree).

#include <cstdlib>
#include <cstring>

namespace parafluid::common
{
enum class SimdLevel
{
  Baseline,
  Avx2,
  Avx512
};

/// The widest copy this CPU runs, capped by PARAFLUID_SIMD (read once).
inline SimdLevel simdLevel()
{
  static const SimdLevel level = []
  {
    __builtin_cpu_init();
    SimdLevel best = SimdLevel::Baseline;
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("fma"))
    {
      best = SimdLevel::Avx512;
    }
    else if (__builtin_cpu_supports("avx2"))
    {
      best = SimdLevel::Avx2;
    }
    const char* cap = std::getenv("PARAFLUID_SIMD");
    if (cap && std::strcmp(cap, "baseline") == 0)
    {
      return SimdLevel::Baseline;
    }
    if (cap && std::strcmp(cap, "avx2") == 0 && best == SimdLevel::Avx512)
    {
      return SimdLevel::Avx2;
    }
    return best;
  }();
  return level;
}
} // namespace parafluid::common

// The Skylake-SP instruction sets, tuned as an Ice Lake server (which gathers) with 512-bit vectors.
#define PARAFLUID_TARGET_AVX512                                                                                        \
  __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,avx512cd,fma,tune=icelake-server,"                         \
                        "prefer-vector-width=512")))
// As GCC's "avx2" clone was: AVX2 without FMA, so its sums round as the baseline's do.
#define PARAFLUID_TARGET_AVX2 __attribute__((target("avx2")))

/// Defines `void name params` to call `body args` (an always_inline function taking the same
/// arguments) compiled as the three copies, the widest this CPU runs picked at each call. The
/// AVX-512 copy's tuning differs from the rest of the program's, and GCC then inlines into it only
/// functions marked always_inline: a body that calls std:: functions (std::vector::data,
/// std::sqrt(float)) runs them as calls and does not vectorise; give it raw pointers and builtins.
/// Constructors too: on an Emerald Rapids core a call from the AVX-512 copy into the program's
/// SSE code cost about 700 cycles (a clouds row read, 3 such calls a block: 28.7 against 7.7 ns
/// a read with the constructor inlined); `objdump -d` of a copy should show no `call`.
#define PARAFLUID_SIMD_DISPATCH(name, params, args, body)                                                              \
  PARAFLUID_TARGET_AVX512 static void name##Avx512 params                                                              \
  {                                                                                                                    \
    body args;                                                                                                         \
  }                                                                                                                    \
  PARAFLUID_TARGET_AVX2 static void name##Avx2 params                                                                  \
  {                                                                                                                    \
    body args;                                                                                                         \
  }                                                                                                                    \
  static void name##Baseline params                                                                                    \
  {                                                                                                                    \
    body args;                                                                                                         \
  }                                                                                                                    \
  void name params                                                                                                     \
  {                                                                                                                    \
    switch (::parafluid::common::simdLevel())                                                                          \
    {                                                                                                                  \
      case ::parafluid::common::SimdLevel::Avx512:                                                                     \
        name##Avx512 args;                                                                                             \
        return;                                                                                                        \
      case ::parafluid::common::SimdLevel::Avx2:                                                                       \
        name##Avx2 args;                                                                                               \
        return;                                                                                                        \
      default:                                                                                                         \
        name##Baseline args;                                                                                           \
    }                                                                                                                  \
  }
