#pragma once
// Core tests that should hold for every pressure solver run once per entry of the solver registry
// (a new solver is tested by adding its entry): derive the suite from EverySolverTest, write
// TEST_P, and instantiate it with PARAFLUID_FOR_EVERY_SOLVER(Suite).
#include "parafluid/sph/SolverRegistry.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace parafluid::sph
{
/// How gtest names a solver parameter in messages and test lists: by its key.
inline void PrintTo(const SolverEntry& entry, std::ostream* os)
{
  *os << entry.key;
}
} // namespace parafluid::sph

namespace parafluid::testing
{
class EverySolverTest : public ::testing::TestWithParam<parafluid::sph::SolverEntry>
{
};

inline std::string solverKey(const ::testing::TestParamInfo<parafluid::sph::SolverEntry>& info)
{
  return info.param.key;
}
} // namespace parafluid::testing

#define PARAFLUID_FOR_EVERY_SOLVER(Suite)                                                                              \
  INSTANTIATE_TEST_SUITE_P(Registry, Suite, ::testing::ValuesIn(parafluid::sph::solverRegistry()),                     \
                           parafluid::testing::solverKey)
