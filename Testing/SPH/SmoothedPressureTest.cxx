// The pressure SPH Step outputs (SPHSolver::smoothedPressure): a linear fit over each particle's
// neighbourhood, read at the particle. It must reproduce a linear field exactly where the
// neighbourhood is cut by a free surface or a wall (the Shepard mean it replaced read a resting
// column's top layer at its neighbours' depth, about twice its own pressure), and still average out
// the layer-by-layer alternating pattern a collocated pressure gradient cannot see.
#include "parafluid/common/Kernels.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.01f; // [m]
constexpr float kSoundSpeed = 20.0f;

SPHParameters deltaSPH(const std::array<float, 6>& domain, const std::array<float, 3>& gravity)
{
  SPHParameters p;
  p.pressureSolver = PressureSolverType::DeltaSPH;
  p.smoothingLength = kDeltaSPHSupport * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = domain;
  p.gravity = gravity;
  p.soundSpeed = kSoundSpeed;
  p.threads = 1;
  return p;
}

/// A δ-SPH solver on a lattice filling `box`, each particle's density set so that its Tait
/// pressure is pressure(x, y, z) (δ-SPH keeps a given density; its pressure follows from it).
SPHSolver withPressure(const SPHParameters& p, const std::array<double, 6>& box,
                       const std::function<double(double, double, double)>& pressure)
{
  auto l = fillBoxWithLattice(box, kSpacing);
  ParticleState start = ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z));
  const double stiffness = p.restDensity * kSoundSpeed * kSoundSpeed / 7.0;
  start.density.resize(start.size());
  for (std::size_t i = 0; i < start.size(); ++i)
  {
    const double value = pressure(start.x[i], start.y[i], start.z[i]);
    start.density[i] = static_cast<float>(p.restDensity * std::pow(1.0 + value / stiffness, 1.0 / 7.0));
  }
  return SPHSolver(p, std::move(start));
}

TEST(SmoothedPressure, ReadsAHydrostaticColumnExactlyUpToItsSurfaceAndWalls)
{
  // A column 8 x 4 x 12 spacings in a walled box, started by δ-SPH in hydrostatic equilibrium:
  // every particle's pressure is rho0 g depth, a linear field cut by the floor, the side walls and
  // the free surface.
  const float w = 8 * kSpacing, t = 4 * kSpacing, h = 12 * kSpacing;
  const SPHParameters p = deltaSPH({ 0, w, 0, t, 0, 2 * h }, { 0, 0, -9.81f });
  const std::array<double, 6> box = { 0, w, 0, t, 0, h };
  auto l = fillBoxWithLattice(box, kSpacing);
  const SPHSolver s(p, ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z)));
  const std::vector<float> smoothed = s.smoothedPressure();
  const ParticleState& st = s.state();
  const double scale = p.restDensity * 9.81 * h; // the floor's pressure
  double worst = 0.0, worstTop = 0.0;
  for (std::size_t i = 0; i < st.size(); ++i)
  {
    const double departure = std::fabs(smoothed[i] - st.pressure[i]) / scale;
    worst = std::max(worst, departure);
    if (st.z[i] > h - kSpacing)
    {
      worstTop = std::max(worstTop, departure);
    }
  }
  std::printf("largest departure from the particles' own pressure: %.2e (top layer %.2e) of rho0 g H\n", worst,
              worstTop);
  // The Shepard mean (with evenly reflected wall images) read the top layer 3.7 % of rho0 g H off.
  EXPECT_LT(worst, 5e-4);
}

TEST(SmoothedPressure, ReproducesALinearFieldOnAFlatSheetOneParticleThick)
{
  // No spread across the sheet: the fit takes no gradient across it (the floor on the spread)
  // instead of dividing by zero, and within it stays exact up to its edges.
  // The sheet lies well inside the box: its edges are free, not mirrored by walls.
  const float side = 12 * kSpacing;
  const SPHParameters p = deltaSPH({ -side, 2 * side, -side, 2 * side, -side, 2 * side }, { 0, 0, 0 });
  const std::array<double, 6> box = { 0, side, 0, side, 0.5 * side, 0.5 * side + kSpacing };
  const SPHSolver s = withPressure(p, box, [](double x, double y, double) { return 2000.0 + 5e4 * x - 2e4 * y; });
  const std::vector<float> smoothed = s.smoothedPressure();
  const ParticleState& st = s.state();
  double worst = 0.0;
  for (std::size_t i = 0; i < st.size(); ++i)
  {
    ASSERT_TRUE(std::isfinite(smoothed[i]));
    worst = std::max(worst, std::fabs(static_cast<double>(smoothed[i]) - st.pressure[i]));
  }
  std::printf("%zu particles in the sheet, largest departure %.3f Pa\n", st.size(), worst);
  EXPECT_GT(st.size(), 100u);
  EXPECT_LT(worst, 1.0); // of pressures 2-8 kPa
}

TEST(SmoothedPressure, AveragesOutAPatternThatAlternatesLayerByLayer)
{
  // A periodic block whose pressure alternates by +-500 Pa from one z layer to the next around
  // 3 kPa: a collocated SPH gradient exerts no force on it, so it is noise, not a field.
  const float side = 12 * kSpacing;
  SPHParameters p = deltaSPH({ 0, side, 0, side, 0, side }, { 0, 0, 0 });
  p.periodic = { true, true, true };
  const SPHSolver s = withPressure(p, { 0, side, 0, side, 0, side },
                                   [](double, double, double z)
                                   {
                                     const auto layer = static_cast<long>(std::floor(z / kSpacing));
                                     return 3000.0 + (layer % 2 == 0 ? 500.0 : -500.0);
                                   });
  const std::vector<float> smoothed = s.smoothedPressure();
  double worst = 0.0;
  for (float value : smoothed)
  {
    worst = std::max(worst, std::fabs(value - 3000.0));
  }
  std::printf("largest departure from the mean: %.1f Pa (the pattern: 500 Pa)\n", worst);
  EXPECT_LT(worst, 100.0);
}
} // namespace
