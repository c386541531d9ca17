// The Müller kernels: unit integral, consistent derivatives, antisymmetric gradients.
#include "parafluid/common/Kernels.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>

namespace
{
using namespace parafluid;

/// 4π ∫_0^h W(r) r² dr by composite Simpson (double precision accumulation).
double radialIntegral(const std::function<double(double)>& w, double h, int intervals = 20000)
{
  const double step = h / intervals;
  double sum = 0.0;
  for (int i = 0; i <= intervals; ++i)
  {
    const double r = i * step;
    const double f = r > 0.0 ? w(r) * r * r : 0.0;
    const double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * f;
  }
  return 4.0 * M_PI * sum * step / 3.0;
}

class KernelRadii : public ::testing::TestWithParam<float>
{
};

TEST_P(KernelRadii, EachKernelIntegratesToOne)
{
  const float h = GetParam();
  const Poly6Kernel poly6(h);
  const SpikyKernel spiky(h);
  const ViscosityKernel viscosity(h);
  EXPECT_NEAR(radialIntegral([&](double r) { return poly6.valueFromSquared(float(r * r)); }, h), 1.0, 1e-3);
  EXPECT_NEAR(radialIntegral([&](double r) { return spiky.value(float(r)); }, h), 1.0, 1e-3);
  EXPECT_NEAR(radialIntegral([&](double r) { return viscosity.value(float(r)); }, h), 1.0, 1e-3);
}

TEST_P(KernelRadii, KernelsVanishAtAndBeyondTheSupportRadius)
{
  const float h = GetParam();
  EXPECT_EQ(Poly6Kernel(h).valueFromSquared(h * h), 0.0f);
  EXPECT_EQ(SpikyKernel(h).value(h), 0.0f);
  EXPECT_EQ(SpikyKernel(h).radialDerivative(1.5f * h), 0.0f);
  EXPECT_EQ(ViscosityKernel(h).laplacian(2.0f * h), 0.0f);
}

TEST_P(KernelRadii, SpikyDerivativeMatchesFiniteDifferences)
{
  const float h = GetParam();
  const SpikyKernel spiky(h);
  for (double q = 0.05; q < 0.95; q += 0.05)
  {
    const double r = q * h;
    const double e = 1e-4 * h;
    const double numeric = (double(spiky.value(float(r + e))) - spiky.value(float(r - e))) / (2 * e);
    EXPECT_NEAR(spiky.radialDerivative(float(r)), numeric, 2e-3 * std::fabs(numeric)) << "r/h = " << q;
  }
}

TEST_P(KernelRadii, ViscosityLaplacianMatchesFiniteDifferences)
{
  // ∇²W = W'' + 2 W' / r for a radial function, evaluated in double from the kernel formula.
  const double h = GetParam();
  const ViscosityKernel viscosity(static_cast<float>(h));
  const double c = 15.0 / (2.0 * M_PI * h * h * h);
  auto w = [&](double r) { return c * (-r * r * r / (2 * h * h * h) + r * r / (h * h) + h / (2 * r) - 1.0); };
  for (double q = 0.1; q < 0.95; q += 0.05)
  {
    const double r = q * h;
    const double e = 1e-4 * h;
    const double second = (w(r + e) - 2 * w(r) + w(r - e)) / (e * e);
    const double first = (w(r + e) - w(r - e)) / (2 * e);
    const double numeric = second + 2.0 * first / r;
    EXPECT_NEAR(viscosity.laplacian(static_cast<float>(r)), numeric, 1e-3 * std::fabs(numeric)) << "r/h = " << q;
    EXPECT_NEAR(viscosity.value(static_cast<float>(r)), w(r), 1e-4 * std::fabs(w(r)) + 1e-3);
  }
}

INSTANTIATE_TEST_SUITE_P(Radii, KernelRadii, ::testing::Values(0.01f, 0.04f, 1.0f, 3.5f));

TEST(SpikyGradient, IsAntisymmetricUnderSwappingThePair)
{
  const float h = 0.1f;
  const SpikyKernel spiky(h);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.06f, 0.06f);
  auto gradient = [&](const std::array<float, 3>& d)
  {
    const float r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const float s = spiky.radialDerivative(r) / r;
    return std::array<float, 3>{ s * d[0], s * d[1], s * d[2] };
  };
  int nonZero = 0;
  for (int k = 0; k < 1000; ++k)
  {
    const std::array<float, 3> xi = { u(rng), u(rng), u(rng) };
    const std::array<float, 3> xj = { u(rng), u(rng), u(rng) };
    const auto gij = gradient({ xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2] });
    const auto gji = gradient({ xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2] });
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_FLOAT_EQ(gij[a], -gji[a]);
      nonZero += gij[a] != 0.0f;
    }
    // The gradient points from j to i (it pushes i away from j under positive pressure) with a
    // negative dW/dr: the dot product with (xi - xj) is never positive.
    EXPECT_LE(gij[0] * (xi[0] - xj[0]) + gij[1] * (xi[1] - xj[1]) + gij[2] * (xi[2] - xj[2]), 0.0f);
  }
  EXPECT_GT(nonZero, 1000); // the test exercised pairs inside the support
}
} // namespace
