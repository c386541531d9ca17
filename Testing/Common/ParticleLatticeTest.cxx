#include "parafluid/common/ParticleLattice.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace
{
TEST(ParticleLattice, FillsTheBoxWithCellCentredLayers)
{
  const auto lattice = parafluid::fillBoxWithLattice({ 0.0, 0.4, -0.1, 0.1, 1.0, 1.3 }, 0.1);
  EXPECT_EQ(lattice.counts[0], 4);
  EXPECT_EQ(lattice.counts[1], 2);
  EXPECT_EQ(lattice.counts[2], 3);
  ASSERT_EQ(lattice.x.size(), 24u);
  EXPECT_FLOAT_EQ(lattice.x.front(), 0.05f);
  EXPECT_FLOAT_EQ(lattice.y.front(), -0.05f);
  EXPECT_FLOAT_EQ(lattice.z.back(), 1.25f);
  for (std::size_t i = 0; i < lattice.x.size(); ++i)
  {
    EXPECT_GT(lattice.x[i], 0.0f);
    EXPECT_LT(lattice.x[i], 0.4f);
  }
}

TEST(ParticleLattice, RejectsAbsurdRequests)
{
  EXPECT_THROW(parafluid::fillBoxWithLattice({ 0, 1, 0, 1, 0, 1 }, 0.0), std::invalid_argument);
  EXPECT_THROW(parafluid::fillBoxWithLattice({ 1, 0, 0, 1, 0, 1 }, 0.1), std::invalid_argument);
  EXPECT_THROW(parafluid::fillBoxWithLattice({ 0, 1, 0, 1, 0, 1 }, 1e-4, 1000), std::invalid_argument);
  EXPECT_TRUE(parafluid::fillBoxWithLattice({ 0, 0.05, 0, 1, 0, 1 }, 0.1).x.empty());
}
} // namespace
