// Short versions of the validation scenes (Testing/SPH/Validation; the full runs, at three
// resolutions, are ParaFluidSPHValidation's): each at its coarsest resolution (the vortex at its
// middle one, the coarsest that holds together), checked against what that resolution reaches, so
// a regression of the physics fails here. The targets of the issue and how far each solver gets
// are in Testing/Benchmarks/README.md.
#include "SPHScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
using namespace parafluid;
using namespace parafluid::validation;
using sph::PressureSolverType;

TEST(SPHValidation, HydrostaticPressureForEverySolver)
{
  // Müller's seed method used to hold water up with twice the hydrostatic pressure (113 % error):
  // its symmetrised force returned half the gradient. The output pressure is a linear fit read at
  // each particle since 2026-11-29 (SPHSolver::smoothedPressure): δ-SPH's column is within the
  // issue's 1 % (1.2 % with the Shepard mean before, whose top layer read its neighbours' depth),
  // while Müller's top layer now shows the zero pressure of its clamped equation of state (1.67 %,
  // 1.43 % before) and DFSPH's its pressure noise (2.7 %, 2.1 % before).
  const struct
  {
    PressureSolverType solver;
    int across;
    double bound;
  } cases[] = { { PressureSolverType::DeltaSPH, 20, 0.01 },
                { PressureSolverType::WCSPH, 20, 0.025 },
                { PressureSolverType::DFSPH, 10, 0.035 } };
  for (const auto& c : cases)
  {
    const Hydrostatic r = hydrostatic(c.solver, c.across);
    std::printf("%s at %d across: relative L2 error %.4f (layers' means %.4f, scatter within layers %.4f)\n",
                solverName(c.solver), c.across, r.error, r.layerMeanError, r.withinLayerError);
    EXPECT_LT(r.error, c.bound) << solverName(c.solver);
    EXPECT_NEAR(r.error * r.error, r.layerMeanError * r.layerMeanError + r.withinLayerError * r.withinLayerError, 1e-9)
      << solverName(c.solver);
  }
}

TEST(SPHValidation, DeltaSPHStillWaterStaysStillAndHydrostatic)
{
  const StillWater r = stillWater(PressureSolverType::DeltaSPH, 10, 10.0);
  std::printf("still water: largest speed %.2e sqrt(gH), pressure error %.4f, drift %.3f spacings\n", r.largestSpeed,
              r.pressureError, r.highestDrift);
  // Issue 21's target: the largest speed over the last second under 1e-3 sqrt(gH). Before a wall's
  // push on a particle by its own image grew all the way to the wall, a floor particle sank onto the
  // floor after about a second (closest 0.00 spacings) and set the tank moving at 2.6-3.9e-3; then
  // 1.2-1.9e-3, the top layers creeping (drift 0.6 spacings) as the density diffusion pumped their
  // steady departure from hydrostatic between them; since the diffusion at a free surface takes
  // only the departure's fast part, 7e-5 (drift 0.004 spacings).
  EXPECT_LT(r.largestSpeed, 0.001);
  EXPECT_LT(r.pressureError, 0.05);
  EXPECT_LT(r.highestDrift, 0.1);
  EXPECT_GT(r.closestToWall, 0.3);
}

TEST(SPHValidation, DeltaSPHDamBreakAgainstMartinAndMoyce)
{
  const DamBreak r = martinMoyce(PressureSolverType::DeltaSPH, 10);
  std::printf("dam break: front error mean %.3f max %.3f, column height error mean %.3f max %.3f\n", r.frontMeanError,
              r.frontMaxError, r.heightMeanError, r.heightMaxError);
  EXPECT_LT(r.frontMeanError, 0.15);
  // The 5 % on the residual column, against Martin & Moyce's Table 6 (read 1.2 % mean and
  // 2.5 % at worst here when it landed, 2026-11-28).
  EXPECT_LT(r.heightMeanError, 0.05);
  EXPECT_LT(r.heightMaxError, 0.05);
}

TEST(SPHValidation, DeltaSPHImpactOnTheWallArrivesWhenLobovskysDid)
{
  const Lobovsky r = lobovsky(PressureSolverType::DeltaSPH, 20);
  std::printf("Lobovsky: arrival error %.4f, first peak %.2f at t* %.3f (experiment %.2f at 2.450)\n", r.frontError,
              r.peakPressure, r.peakTime, 2.843);
  EXPECT_LT(r.frontError, 0.02);
  EXPECT_LT(r.peakTimeError, 0.05);
  // The first peak is the artificial sound speed's water hammer, several times the experiment's
  // 2.84 (issue 21's 20 % is not met); with the front's particles running into their own soft
  // wall images it was 49, with the own image's push growing towards the wall about 26, and with
  // the wall images' pressure extrapolated hydrostatically (the gradient correction's wall) 33
  // (34.4 since the density diffusion at a free surface leaves the departure's slow part alone),
  // each read as a mean over 0.5 ms. Read after every step, as now, it is 34.3, and 36.3 where the
  // steps fall differently around the impact (a run stepped straight through it): the bound is a
  // guard against the soft walls' 49, not the target.
  EXPECT_LT(r.peakPressure, 40.0);
}

TEST(SPHValidation, StandingWaveFrequency)
{
  // Issue 21's 1 %. Without the gradient correction the sheared lattice pushed back like an
  // elastic solid under the water's weight and the wave ran 2.0 % fast at this resolution; at the
  // default 2.9 spacings without the push's high pass, 2.1 % (0.9 % with it).
  const StandingWave r = standingWave(PressureSolverType::DeltaSPH, 10);
  std::printf("standing wave: omega %.4f, exact %.4f, error %.4f\n", r.frequency, r.exact, r.frequencyError);
  EXPECT_LT(r.frequencyError, 0.01);
}

TEST(SPHValidation, DeltaSPHTaylorGreenVortexDecaysAtItsViscousRate)
{
  // Re = 100. With a shifting too weak to keep the particles apart at the stagnation points, the
  // vortex broke down into particle noise at t U / L = 0.15 and had lost 61 % more energy than the
  // analytic decay by one decay time; with Monaghan's viscous operator, corrected for shear along
  // the lattice's axes, it decayed 6 % too fast all along (13.6 %). Morris's operator: 4.7 % at 25
  // across, but that start had every particle at another's density (the constructor's sort left
  // the given density behind): started with the vortex's own pressure, the 25-across vortex partly
  // breaks down at t U / L = 0.1-0.15 (13 %), and 50 across is the coarsest that holds (0.4 %).
  const TaylorGreen r = taylorGreen(PressureSolverType::DeltaSPH, 50);
  std::printf("Taylor-Green at 50 across: largest error of the energy decay %.4f\n", r.decayError);
  EXPECT_LT(r.decayError, 0.02);
}

TEST(SPHValidation, DeltaSPHPoiseuilleProfile)
{
  // The same viscous operator holds the layered shear between plates (1.7 % at 10 across): its
  // lattice error is the same for every direction of shear, so one correction serves both flows.
  const Poiseuille r = poiseuille(PressureSolverType::DeltaSPH, 10);
  std::printf("Poiseuille (δ-SPH): largest error %.4f of the peak\n", r.profileError);
  EXPECT_LT(r.profileError, 0.025);
}

TEST(SPHValidation, DeltaSPHPressurisedLatticeStaysAtRestAtTheDefaultSupport)
{
  // Under pressure the symmetric force's 2 p_i term gives the simple cubic lattice shear moduli of
  // either sign, by the kernel's support (Testing/Benchmarks/lattice_stability.py): negative at 3
  // spacings, where this block grows a transverse wave of six spacings to 7e-3 m/s rms in 1.5 s
  // (6e-3 with the push's high pass: the 40-across still-water tank's interior event), positive
  // at 2.8-2.9. At the default 2.9, high pass on, it must stay at the seed's 1e-5 m/s: it would not
  // if the pressure forces on a regular lattice did not cancel, or if the block were not under its
  // 3.9 kPa.
  ASSERT_EQ(kernelRatio(PressureSolverType::DeltaSPH), sph::kDeltaSPHSupport);
  const PressurisedLattice r = pressurisedLattice(PressureSolverType::DeltaSPH, 10);
  std::printf("pressurised lattice at %.2f spacings: rms speed %.2e m/s, largest %.2e m/s, mean pressure %.0f Pa\n",
              kernelRatio(PressureSolverType::DeltaSPH), r.rmsSpeed, r.largestSpeed, r.meanPressure);
  EXPECT_LT(r.rmsSpeed, 1e-4);
  EXPECT_LT(r.largestSpeed, 2e-4);
  EXPECT_NEAR(r.meanPressure, kRho0 * kGravity * 0.4, 200.0);
}

TEST(SPHValidation, DFSPHPoiseuilleProfile)
{
  const Poiseuille r = poiseuille(PressureSolverType::DFSPH, 10);
  std::printf("Poiseuille (DFSPH, implicit viscosity): largest error %.4f of the peak, %d CG iterations a step\n",
              r.profileError, r.viscosityIterations);
  EXPECT_LT(r.profileError, 0.08);
  EXPECT_GT(r.viscosityIterations, 0);
}

TEST(SPHValidation, SolveLimitProbesReachTheScenesAndReset)
{
  // ParaFluidSPHValidation's --density-tolerance and --max-time-step: the scenes' water carries
  // them, and 0 gives the solver's defaults back.
  const std::array<float, 6> box = { 0.0f, 0.2f, 0.0f, 0.02f, 0.0f, 0.4f };
  const sph::SPHParameters defaults = water(PressureSolverType::DFSPH, 0.01f, box);
  setSolveLimits(1e-5f, 2e-3f);
  const sph::SPHParameters probed = water(PressureSolverType::DFSPH, 0.01f, box);
  setSolveLimits(0.0f, 0.0f);
  const sph::SPHParameters restored = water(PressureSolverType::DFSPH, 0.01f, box);
  EXPECT_FLOAT_EQ(probed.densityTolerance, 1e-5f);
  EXPECT_FLOAT_EQ(probed.maxTimeStep, 2e-3f);
  EXPECT_NE(defaults.densityTolerance, probed.densityTolerance);
  EXPECT_NE(defaults.maxTimeStep, probed.maxTimeStep);
  EXPECT_EQ(restored.densityTolerance, defaults.densityTolerance);
  EXPECT_EQ(restored.maxTimeStep, defaults.maxTimeStep);
}

TEST(SPHValidation, HydrostaticErrorSplitsIntoLayerOffsetsAndScatter)
{
  // Two particles in each of three layers one spacing (0.1 m) thick, under a 0.3 m column.
  const std::vector<double> z = { 0.05, 0.06, 0.15, 0.16, 0.25, 0.26 };
  std::vector<double> reference(z.size());
  for (std::size_t i = 0; i < z.size(); ++i)
  {
    reference[i] = 9810.0 * (0.3 - z[i]);
  }
  double referenceSquares = 0.0;
  for (double r : reference)
  {
    referenceSquares += r * r;
  }
  // Offsets only (each layer's two particles depart alike): all of it is the layers' means.
  const double offset[3] = { 30.0, -10.0, 20.0 };
  std::vector<double> shifted(z.size()), scattered(z.size()), both(z.size());
  for (std::size_t i = 0; i < z.size(); ++i)
  {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    shifted[i] = reference[i] + offset[i / 2];
    scattered[i] = reference[i] + 15.0 * sign; // each layer's mean departure is zero
    both[i] = reference[i] + offset[i / 2] + 15.0 * sign;
  }
  const double offsetsAlone = std::sqrt(2.0 * (30.0 * 30.0 + 10.0 * 10.0 + 20.0 * 20.0) / referenceSquares);
  const double scatterAlone = std::sqrt(6.0 * 15.0 * 15.0 / referenceSquares);
  const ErrorByDepth a = splitErrorByDepth(z, shifted, reference, 0.1);
  EXPECT_NEAR(a.total, offsetsAlone, 1e-12);
  EXPECT_NEAR(a.layerMean, offsetsAlone, 1e-12);
  EXPECT_NEAR(a.withinLayer, 0.0, 1e-12);
  const ErrorByDepth b = splitErrorByDepth(z, scattered, reference, 0.1);
  EXPECT_NEAR(b.total, scatterAlone, 1e-12);
  EXPECT_NEAR(b.layerMean, 0.0, 1e-12);
  EXPECT_NEAR(b.withinLayer, scatterAlone, 1e-12);
  const ErrorByDepth c = splitErrorByDepth(z, both, reference, 0.1);
  EXPECT_NEAR(c.layerMean, offsetsAlone, 1e-12);
  EXPECT_NEAR(c.withinLayer, scatterAlone, 1e-12);
  EXPECT_NEAR(c.total * c.total, c.layerMean * c.layerMean + c.withinLayer * c.withinLayer, 1e-15);
  // Layers of one spacing: with 0.2 m layers the first two pairs share a layer, whose mean is 10,
  // so the split moves (the total does not).
  const ErrorByDepth wide = splitErrorByDepth(z, shifted, reference, 0.2);
  EXPECT_NEAR(wide.total, offsetsAlone, 1e-12);
  EXPECT_GT(wide.withinLayer, 0.0);
  // A particle gone astray (a non-finite height) is a layer of its own, not a crash.
  std::vector<double> strayZ = z, strayValue = shifted, strayReference = reference;
  strayZ.push_back(std::nan(""));
  strayValue.push_back(1.0);
  strayReference.push_back(0.0);
  const ErrorByDepth stray = splitErrorByDepth(strayZ, strayValue, strayReference, 0.1);
  EXPECT_TRUE(std::isfinite(stray.total));
  EXPECT_NEAR(stray.withinLayer, 0.0, 1e-12);
}
} // namespace
