#include "SPHScenes.h"

#include "parafluid/sph/SolverRegistry.h"

#include "parafluid/common/ParticleLattice.h"

namespace parafluid::validation
{
using sph::PressureSolverType;

namespace
{
// h / spacing per solver: Müller's and DFSPH's 2 (DFSPH's Jacobi solves need <= 2.25); δ-SPH's
// default, 2.9 (sph::kDeltaSPHSupport: at 2 its standing waves run 14 % fast, at 3 its pressurised
// lattice shears apart; see the README).
float gKernelRatio[3] = { 2.0f, 2.0f, sph::kDeltaSPHSupport };
bool gPushHighPass = true;
float gDensityTolerance = 0.0f; // 0: the solver's default
float gMaxTimeStep = 0.0f;      // 0: the solver's default
}

void setSolveLimits(float densityTolerance, float maxTimeStep)
{
  gDensityTolerance = densityTolerance;
  gMaxTimeStep = maxTimeStep;
}

void setPushHighPass(bool on)
{
  gPushHighPass = on;
}

void setKernelRatio(PressureSolverType solver, float ratio)
{
  gKernelRatio[static_cast<int>(solver)] = ratio;
}

float kernelRatio(PressureSolverType solver)
{
  return gKernelRatio[static_cast<int>(solver)];
}

const char* solverName(PressureSolverType solver)
{
  return sph::solverEntry(solver).key;
}

sph::SPHParameters water(PressureSolverType solver, float spacing, const std::array<float, 6>& domain)
{
  sph::SPHParameters p;
  p.pressureSolver = solver;
  p.smoothingLength = kernelRatio(solver) * spacing;
  p.restDensity = kRho0;
  p.viscosity = solver == PressureSolverType::WCSPH ? 3.5f : 0.0f;
  p.gravity = { 0.0f, 0.0f, -kGravity };
  p.domainBounds = domain;
  p.particleMass = sph::latticeParticleMass(spacing, p.smoothingLength, kRho0, p.densityKernel());
  p.pushHighPass = gPushHighPass;
  if (gDensityTolerance > 0.0f)
  {
    p.densityTolerance = gDensityTolerance;
  }
  if (gMaxTimeStep > 0.0f)
  {
    p.maxTimeStep = gMaxTimeStep;
  }
  return p;
}

ParticleState lattice(const std::array<double, 6>& box, double spacing)
{
  auto l = fillBoxWithLattice(box, spacing);
  return ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z));
}
} // namespace parafluid::validation
