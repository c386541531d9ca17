// Akinci et al. (2013) surface tension: a weightless cube of water pulls itself round, at the
// millimetre scale where the colour-field force is noisy, without clumping particles, and a
// stretched drop oscillates at Rayleigh's frequency.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHSolver.h"

#include "SPHScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.0005f; // 0.5 mm: a cube of 5 mm

/// The ratio of the largest to the smallest distance from the centre of the particles on the
/// outside (those farther out than 80 % of the largest): sqrt(3) for a cube, 1 for a sphere.
double roundness(const ParticleState& s)
{
  double c[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    c[0] += s.x[i];
    c[1] += s.y[i];
    c[2] += s.z[i];
  }
  for (double& v : c)
  {
    v /= static_cast<double>(s.size());
  }
  double largest = 0.0;
  std::vector<double> r(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    r[i] = std::sqrt((s.x[i] - c[0]) * (s.x[i] - c[0]) + (s.y[i] - c[1]) * (s.y[i] - c[1]) +
                     (s.z[i] - c[2]) * (s.z[i] - c[2]));
    largest = std::max(largest, r[i]);
  }
  // The smallest distance of the outermost particle along each axis direction: the cube's faces.
  double faces = largest;
  for (int a = 0; a < 3; ++a)
  {
    for (int sign : { -1, 1 })
    {
      double extreme = 0.0;
      for (std::size_t i = 0; i < s.size(); ++i)
      {
        const double v = (a == 0 ? s.x[i] - c[0] : a == 1 ? s.y[i] - c[1] : s.z[i] - c[2]) * sign;
        extreme = std::max(extreme, v);
      }
      faces = std::min(faces, extreme);
    }
  }
  return largest / faces;
}

TEST(SurfaceTension, AkinciPullsAWeightlessCubeRoundWithoutClumping)
{
  for (PressureSolverType solver : { PressureSolverType::DFSPH, PressureSolverType::DeltaSPH })
  {
    SPHParameters p;
    p.pressureSolver = solver;
    p.smoothingLength = 2.0f * kSpacing;
    p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
    p.domainBounds = { -0.01f, 0.01f, -0.01f, 0.01f, -0.01f, 0.01f };
    p.gravity = { 0, 0, 0 };
    p.surfaceTension = 0.0728f;
    p.surfaceTensionModel = SurfaceTensionModel::Akinci;
    auto l = fillBoxWithLattice({ -0.0025, 0.0025, -0.0025, 0.0025, -0.0025, 0.0025 }, kSpacing);
    SPHSolver s(p, ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z)));
    const double before = roundness(s.state());
    s.advance(0.05);
    const double after = roundness(s.state());
    std::printf("%d: roundness %.3f -> %.3f, max density %.4f rho0\n", static_cast<int>(solver), before, after,
                s.lastStep().maxDensityRatio);
    EXPECT_LT(after, before - 0.2 * (before - 1.0)) << "the corners are pulled in";
    EXPECT_LT(s.lastStep().maxDensityRatio, 1.05) << "no clumps";
    // Without tension nothing moves.
    p.surfaceTension = 0.0f;
    auto m = fillBoxWithLattice({ -0.0025, 0.0025, -0.0025, 0.0025, -0.0025, 0.0025 }, kSpacing);
    SPHSolver still(p, ParticleState::atRest(std::move(m.x), std::move(m.y), std::move(m.z)));
    still.advance(0.05);
    EXPECT_NEAR(roundness(still.state()), before, 0.05 * before);
  }
}

TEST(SurfaceTension, AkinciDropOscillatesAtRayleighsFrequency)
{
  // A weightless water drop of radius 2.5 mm, 8 particles across its radius, stretched 10 % along
  // x, oscillates in its l = 2 mode at Rayleigh's period (32.8 ms) over 2.5 periods. Both of
  // Akinci's terms are on, scaled together to sigma (SurfaceTension.cxx); nothing in that scaling
  // is fitted to a drop. (The cohesion alone does not oscillate: it fails here.) Over 1.5 periods
  // (3 zero crossings) the release's first swing weighs on the period: since δ-SPH's support is 2.9
  // spacings with the push's high pass it read 33.53 ms in the Release build and 34.45 ms (5.1 %)
  // in the sanitizer build; over 2.5 periods 33.29 ms (Release) and 33.96 ms (sanitizer), over 3
  // periods 32.57 ms (Release).
  const validation::Drop drop =
    validation::oscillatingDrop(PressureSolverType::DeltaSPH, 8, nullptr, SurfaceTensionModel::Akinci, 0.1, 0.08);
  std::printf("drop: %d zero crossings, period %.2f ms, Rayleigh %.2f ms (sigma_eff / sigma %.3f), largest density "
              "%.4f rho0\n",
              drop.crossings, drop.period * 1e3, drop.rayleigh * 1e3, drop.sigmaRatio, drop.largestDensity);
  ASSERT_GE(drop.crossings, 3) << "the drop oscillates";
  EXPECT_LT(drop.periodError, 0.05);
  EXPECT_LT(drop.largestDensity, 1.05) << "no clumps";
}

TEST(SurfaceTension, ColourFieldWithDeltaSPHIsRefusedByName)
{
  // δ-SPH has its own force pass, without the colour field: asking for it must not silently give
  // no surface tension at all.
  SPHParameters p;
  p.pressureSolver = PressureSolverType::DeltaSPH;
  p.particleMass = 1e-3f;
  p.smoothingLength = 0.03f;
  p.surfaceTension = 0.0728f;
  p.surfaceTensionModel = SurfaceTensionModel::ColourField;
  EXPECT_NE(p.validate().find("SurfaceTensionModel"), std::string::npos);
  p.surfaceTensionModel = SurfaceTensionModel::Akinci;
  EXPECT_EQ(p.validate(), "");
  p.surfaceTensionModel = SurfaceTensionModel::ColourField;
  p.pressureSolver = PressureSolverType::WCSPH;
  EXPECT_EQ(p.validate(), "");
}
} // namespace
