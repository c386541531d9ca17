// Dispersion of gravity waves: the shoaling wavenumber solves k tanh(k h) = k_deep, and the closed
// form the GPU uses is as close as its documentation says.
#include "parafluid/ocean/WaveDispersion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
using namespace parafluid::ocean;

TEST(WaveDispersion, ShoalingWavenumberSolvesTheDispersionRelation)
{
  const double kDeep = 0.3;
  for (double kh = 1e-4; kh < 60.0; kh *= 1.3)
  {
    const double h = kh / kDeep;
    const double k = shoalingWavenumber(kDeep, h);
    EXPECT_NEAR(k * std::tanh(k * h), kDeep, 1e-12 * kDeep) << "k_deep h = " << kh;
    EXPECT_GE(k, kDeep) << "waves only get shorter in shallower water";
  }
  // Limits: deep water keeps k_deep; very shallow water gives k = sqrt(k_deep / h), c = sqrt(g h).
  EXPECT_DOUBLE_EQ(shoalingWavenumber(kDeep, kDeepWater), kDeep);
  const double h = 1e-4;
  EXPECT_NEAR(shoalingWavenumber(kDeep, h), std::sqrt(kDeep / h), 1e-4 * std::sqrt(kDeep / h));
  EXPECT_NEAR(phaseSpeed(shoalingWavenumber(kDeep, h), h), std::sqrt(kStandardGravity * h), 1e-4);
  EXPECT_THROW(shoalingWavenumber(kDeep, 0.0), std::invalid_argument);
  EXPECT_THROW(shoalingWavenumber(kDeep, -1.0), std::invalid_argument);
}

TEST(WaveDispersion, ClosedFormApproximationErrorIsAsDocumented)
{
  double worst = 0.0, worstAt = 0.0;
  for (double kh = 1e-4; kh < 50.0; kh *= 1.01)
  {
    const double exact = shoalingWavenumber(1.0, kh), approximate = shoalingWavenumberApproximation(1.0, kh);
    const double error = std::fabs(approximate - exact) / exact;
    if (error > worst)
    {
      worst = error, worstAt = kh;
    }
  }
  EXPECT_LT(worst, 0.050);
  EXPECT_GT(worst, 0.049) << "the documented figure should be tight";
  EXPECT_GT(worstAt, 0.3);
  EXPECT_LT(worstAt, 3.0);
}

TEST(WaveDispersion, FrequencyAndSpeed)
{
  const double k = 2.0 * 3.14159265358979323846 / 20.0;
  EXPECT_NEAR(angularFrequency(k, kDeepWater), std::sqrt(kStandardGravity * k), 1e-12);
  EXPECT_NEAR(phaseSpeed(k, kDeepWater), std::sqrt(kStandardGravity / k), 1e-12);
  EXPECT_NEAR(phaseSpeed(k, 2.0), std::sqrt(kStandardGravity / k * std::tanh(2.0 * k)), 1e-12);
}
} // namespace
