// δ-SPH's particle shifting (SPHParameters::particleShifting): it evens out a disordered particle
// distribution where the fluid moves, by at most 0.2 spacings a step.
#include "parafluid/common/Kernels.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.01f;
constexpr float kSide = 0.1f; // [m] a periodic cube of 10 spacings: every neighbourhood is full

/// A lattice filling the periodic cube with every particle displaced at random by up to `jitter`
/// spacings on each axis, all moving at `speed` along x (a uniform flow: nothing but the shifting
/// changes the particles' arrangement relative to each other).
SPHSolver jitteredFlow(bool shifting, float jitter, float speed)
{
  SPHParameters p;
  p.pressureSolver = PressureSolverType::DeltaSPH;
  p.smoothingLength = 3.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, kSide, 0, kSide, 0, kSide };
  p.periodic = { true, true, true };
  p.gravity = { 0, 0, 0 };
  p.particleShifting = shifting;
  p.adaptiveTimeStep = false;
  p.timeStep = 1e-4f;
  p.threads = 2;
  auto l = fillBoxWithLattice({ 0, kSide, 0, kSide, 0, kSide }, kSpacing);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> offset(-jitter * kSpacing, jitter * kSpacing);
  for (std::size_t i = 0; i < l.x.size(); ++i)
  {
    l.x[i] += offset(random);
    l.y[i] += offset(random);
    l.z[i] += offset(random);
  }
  ParticleState s = ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z));
  std::fill(s.vx.begin(), s.vx.end(), speed);
  return SPHSolver(p, std::move(s));
}

/// Relative spread (standard deviation over mean) of the particles' kernel sums sum_j W_ij: zero
/// on a perfect lattice, larger the more disordered the particles.
double concentrationSpread(const SPHSolver& solver)
{
  const auto& s = solver.state();
  const float h = solver.parameters().smoothingLength;
  const WendlandC2Kernel w(h);
  std::vector<double> sums(s.size(), 0.0);
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    for (std::size_t j = 0; j < s.size(); ++j)
    {
      float d[3] = { s.x[i] - s.x[j], s.y[i] - s.y[j], s.z[i] - s.z[j] };
      for (float& c : d)
      {
        c -= kSide * std::round(c / kSide); // the nearest periodic image
      }
      const float r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      sums[i] += r < h ? w.value(r) : 0.0f;
    }
  }
  double mean = 0.0, square = 0.0;
  for (const double v : sums)
  {
    mean += v;
    square += v * v;
  }
  mean /= static_cast<double>(sums.size());
  return std::sqrt(std::max(square / static_cast<double>(sums.size()) - mean * mean, 0.0)) / mean;
}

TEST(ParticleShifting, EvensOutADisorderedFlowWhereThePlainSchemeDoesNot)
{
  SPHSolver shifted = jitteredFlow(true, 0.25f, 1.0f);
  SPHSolver plain = jitteredFlow(false, 0.25f, 1.0f);
  const double before = concentrationSpread(shifted);
  ASSERT_NEAR(before, concentrationSpread(plain), 1e-12); // the same start
  ASSERT_GT(before, 0.01);
  for (int k = 0; k < 40; ++k)
  {
    shifted.step();
    plain.step();
  }
  const double evened = concentrationSpread(shifted);
  const double left = concentrationSpread(plain);
  // The shift moves particles down the concentration gradient: the spread falls well below the
  // plain scheme's, whose pressure forces alone act over acoustic times (c0 = 10 m/s here).
  EXPECT_LT(evened, 0.5 * before) << "shifting left the spread at " << evened << " of a start of " << before;
  EXPECT_LT(evened, 0.6 * left) << "shifted " << evened << ", plain " << left;
}

TEST(ParticleShifting, MovesAParticleAtMostAFifthOfASpacingAStep)
{
  // One step of a disordered uniform flow: every particle moves by its velocity times the step plus
  // the shift, which is capped at 0.2 spacings.
  SPHSolver moving = jitteredFlow(true, 0.25f, 1.0f);
  const auto before = moving.state();
  moving.step();
  const auto& after = moving.state();
  const double dt = moving.lastStep().timeStep;
  std::vector<std::size_t> byId(after.size());
  for (std::size_t i = 0; i < after.size(); ++i)
  {
    byId[static_cast<std::size_t>(after.id[i])] = i;
  }
  double largestShift = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i)
  {
    const std::size_t k = byId[static_cast<std::size_t>(before.id[i])];
    float d[3] = { after.x[k] - before.x[i] - static_cast<float>(dt) * after.vx[k], after.y[k] - before.y[i],
                   after.z[k] - before.z[i] };
    for (float& c : d)
    {
      c -= kSide * std::round(c / kSide);
    }
    largestShift = std::max(largestShift, static_cast<double>(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])));
  }
  EXPECT_GT(largestShift, 1e-4 * kSpacing); // it does shift
  EXPECT_LE(largestShift, 0.2 * kSpacing + 0.01 * kSpacing);
}
} // namespace
