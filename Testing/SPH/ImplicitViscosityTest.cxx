// DFSPH's implicit viscosity (Weiler et al. 2018): stable at any viscosity with the step the
// pressure solve takes, the two conjugate-gradient implementations agree, and a viscous shear
// layer decays as the diffusion equation says.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHSolver.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.01f;
constexpr float kPi = 3.14159265f;

/// A periodic box with the shear wave u = U sin(2 pi z / L): without pressure (it is divergence
/// free) it decays as exp(-nu (2 pi / L)^2 t).
SPHSolver shearWave(float nu, ViscositySolver cg, float maxStep)
{
  SPHParameters p;
  p.pressureSolver = PressureSolverType::DFSPH;
  p.smoothingLength = 2.0f * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, 0.06f, 0, 0.06f, 0, 0.2f };
  p.periodic = { true, true, true };
  p.gravity = { 0, 0, 0 };
  p.kinematicViscosity = nu;
  p.viscositySolver = cg;
  p.maxTimeStep = maxStep;
  p.viscosityTolerance = 1e-4f;
  auto l = fillBoxWithLattice({ 0, 0.06, 0, 0.06, 0, 0.2 }, kSpacing);
  ParticleState s = ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z));
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    s.vx[i] = 0.01f * std::sin(2.0f * kPi * s.z[i] / 0.2f);
  }
  return SPHSolver(p, std::move(s));
}

double amplitude(const SPHSolver& s)
{
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < s.state().size(); ++i)
  {
    const double shape = std::sin(2.0 * kPi * s.state().z[i] / 0.2);
    num += s.state().vx[i] * shape;
    den += shape * shape;
  }
  return num / den;
}

TEST(ImplicitViscosity, ShearWaveDecaysAtTheDiffusionRateWithStepsFarBeyondTheExplicitLimit)
{
  // nu = 1e-3 m^2/s: the explicit limit 0.03 h^2 / nu is 1.2e-5 s; the implicit solve takes
  // steps of 2e-3 s (170 times longer) and still decays at the diffusion equation's rate.
  const float nu = 1e-3f;
  SPHSolver s = shearWave(nu, ViscositySolver::HandWrittenCG, 2e-3f);
  const double start = amplitude(s);
  const std::int64_t steps = s.advance(0.2);
  EXPECT_LT(steps, 200);
  const double k = 2.0 * kPi / 0.2;
  const double exact = std::exp(-nu * k * k * 0.2);
  const double measured = amplitude(s) / start;
  std::printf("shear wave: amplitude %.4f of the start, exact %.4f, %lld steps\n", measured, exact,
              static_cast<long long>(steps));
  EXPECT_NEAR(measured, exact, 0.05 * exact);
}

TEST(ImplicitViscosity, HandWrittenAndEigenConjugateGradientsAgree)
{
  SPHSolver a = shearWave(1e-2f, ViscositySolver::HandWrittenCG, 2e-3f);
  SPHSolver b = shearWave(1e-2f, ViscositySolver::EigenCG, 2e-3f);
  a.advance(0.02);
  b.advance(0.02);
  EXPECT_GT(a.lastStep().viscosityIterations, 1);
  EXPECT_NEAR(amplitude(a), amplitude(b), 1e-3 * std::fabs(amplitude(a)));
}

TEST(ImplicitViscosity, HoneyDoesNotShortenTheStep)
{
  // Honey (nu = 1e-2) collapsing under gravity: DFSPH keeps the steps it takes for water.
  for (float nu : { 1e-6f, 1e-2f })
  {
    SPHParameters p;
    p.pressureSolver = PressureSolverType::DFSPH;
    p.smoothingLength = 2.0f * kSpacing;
    p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
    p.domainBounds = { 0, 0.3f, 0, 0.05f, 0, 0.2f };
    p.kinematicViscosity = nu;
    auto l = fillBoxWithLattice({ 0, 0.1, 0, 0.05, 0, 0.1 }, kSpacing);
    SPHSolver s(p, ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z)));
    const std::int64_t steps = s.advance(0.1);
    std::printf("nu %g: %lld steps for 0.1 s\n", nu, static_cast<long long>(steps));
    EXPECT_LT(steps, 150) << nu;
  }
}
} // namespace
