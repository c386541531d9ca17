// Akinci et al. (2013) surface tension: a weightless cube of water pulls itself round, at the
// millimetre scale where the colour-field force is noisy, without clumping particles.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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
} // namespace
