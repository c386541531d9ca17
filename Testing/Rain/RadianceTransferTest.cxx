// The drop's radiance transfer: energy, the rainbow angles, and the spherical-harmonic projection.
#include "parafluid/rain/DropTransfer.h"
#include "parafluid/rain/SphericalHarmonics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace parafluid::rain;

namespace
{
double peakAngleDegrees(const DropTransfer& drop, int path)
{
  const auto phase = drop.pathPhase(path);
  const auto peak = std::max_element(phase.begin(), phase.end()) - phase.begin();
  return drop.angle(static_cast<int>(peak)) * 180.0 / M_PI;
}
} // namespace

TEST(RadianceTransfer, ClearDropConservesEnergy)
{
  DropTransfer drop;
  RecordProperty("energy", std::to_string(drop.energy()));
  EXPECT_NEAR(drop.energy(), 1.0, 0.01);
  // The zonal band 0 is the same integral, and a white sky of radiance 1 gives radiance 1.
  const auto lambda = drop.zonal();
  EXPECT_NEAR(lambda[0], drop.energy(), 1e-9);
  // An absorbing drop passes less.
  DropTransferSettings murky;
  murky.absorption = 0.5;
  EXPECT_LT(DropTransfer(murky).energy(), 0.95);
}

TEST(RadianceTransfer, RainbowAngles)
{
  DropTransferSettings s;
  s.refractiveIndex = 1.333;
  s.bins = 3600; // 0.05 degree bins
  s.samples = 2000000;
  DropTransfer drop(s);
  const double primary = peakAngleDegrees(drop, 2), secondary = peakAngleDegrees(drop, 3);
  RecordProperty("primary_deg", std::to_string(primary));
  RecordProperty("secondary_deg", std::to_string(secondary));
  EXPECT_GE(primary, 137.5);
  EXPECT_LE(primary, 138.5);
  EXPECT_GE(secondary, 129.0);
  EXPECT_LE(secondary, 130.0);
  // Alexander's dark band: between the bows the two paths send (almost) nothing.
  const auto p2 = drop.pathPhase(2), p3 = drop.pathPhase(3);
  const int band = static_cast<int>(134.0 / 180.0 * s.bins);
  EXPECT_EQ(p2[band], 0.0);
  EXPECT_EQ(p3[band], 0.0);
}

TEST(RadianceTransfer, BandTwoHarmonicReconstructs)
{
  // f = Y_{2,1}: its projection is the unit vector of (2, 1), and it reconstructs everywhere.
  auto f = [](double x, double y, double z) { return shBasis(x, y, z)[shIndex(2, 1)]; };
  const SHVector c = shProject(f, 16);
  for (int k = 0; k < kSHCount; ++k)
  {
    EXPECT_NEAR(c[k], k == shIndex(2, 1) ? 1.0 : 0.0, 1e-10) << k;
  }
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  double worst = 0.0;
  for (int sample = 0; sample < 1000; ++sample)
  {
    double d[3] = { normal(random), normal(random), normal(random) };
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    worst = std::max(worst, std::fabs(shEvaluate(c, d[0] / n, d[1] / n, d[2] / n) - f(d[0] / n, d[1] / n, d[2] / n)));
  }
  EXPECT_LT(worst, 1e-4);
  // The orthonormal basis: a constant 1 projects to sqrt(4 pi) on (0, 0) only.
  const SHVector one = shProject([](double, double, double) { return 1.0; });
  EXPECT_NEAR(one[0], std::sqrt(4.0 * M_PI), 1e-10);
}

TEST(RadianceTransfer, CubeMapProjection)
{
  // The same harmonic drawn into a cube map (texel centres) projects back through the texels'
  // solid angles.
  const int size = 128;
  std::array<std::vector<float>, 6> faces;
  for (int face = 0; face < 6; ++face)
  {
    faces[face].resize(static_cast<std::size_t>(size) * size);
    for (int row = 0; row < size; ++row)
    {
      for (int col = 0; col < size; ++col)
      {
        const double sc = 2.0 * (col + 0.5) / size - 1.0, tc = 2.0 * (row + 0.5) / size - 1.0;
        double d[3];
        switch (face)
        {
          case 0:
            d[0] = 1, d[1] = -tc, d[2] = -sc;
            break;
          case 1:
            d[0] = -1, d[1] = -tc, d[2] = sc;
            break;
          case 2:
            d[0] = sc, d[1] = 1, d[2] = tc;
            break;
          case 3:
            d[0] = sc, d[1] = -1, d[2] = -tc;
            break;
          case 4:
            d[0] = sc, d[1] = -tc, d[2] = 1;
            break;
          default:
            d[0] = -sc, d[1] = -tc, d[2] = -1;
            break;
        }
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        faces[face][static_cast<std::size_t>(row) * size + col] =
          static_cast<float>(shBasis(d[0] / n, d[1] / n, d[2] / n)[shIndex(2, 1)]);
      }
    }
  }
  const auto c = shProjectCubeMap(
    { faces[0].data(), faces[1].data(), faces[2].data(), faces[3].data(), faces[4].data(), faces[5].data() }, size, 1);
  for (int k = 0; k < kSHCount; ++k)
  {
    EXPECT_NEAR(c[k], k == shIndex(2, 1) ? 1.0 : 0.0, 1e-4) << k;
  }
}

TEST(RadianceTransfer, TransferTableIsTheZonalConvolution)
{
  // A sky bright above (radiance 1 + z): a drop seen looking horizontally sends back lambda_0 +
  // lambda_1 * (its forward part), the same from every azimuth.
  DropTransfer drop;
  const auto lambda = drop.zonal();
  const int width = 32, height = 16;
  const auto table = drop.transferTable(width, height);
  const SHVector sky = shProject([](double, double, double z) { return 1.0 + z; });
  for (int row : { 0, 8, 15 })
  {
    const double z = -1.0 + 2.0 * (row + 0.5) / height;
    for (int col = 0; col < width; col += 7)
    {
      double radiance = 0.0;
      for (int k = 0; k < kSHCount; ++k)
      {
        radiance += table[(static_cast<std::size_t>(row) * width + col) * kSHCount + k] * sky[k];
      }
      EXPECT_NEAR(radiance, lambda[0] + lambda[1] * z, 1e-5);
    }
  }
}
