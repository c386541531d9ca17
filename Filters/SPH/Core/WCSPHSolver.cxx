// Weakly compressible SPH (Müller et al. 2003): the poly6 density, the equation of state and the
// kick-drift-kick leapfrog step; the spiky pressure gradient is summed with the other forces in
// SPHSolver::computeAccelerations (SPHForces.cxx).
#include "parafluid/sph/WCSPHSolver.h"

#include "parafluid/common/Kernels.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"
#include "private/WallImages.h"

#include <algorithm>
#include <cmath>

namespace parafluid::sph
{
using detail::CandidateBuffer;
using detail::forEachParticleByCell;
using detail::threadCount;

SolverEntry WCSPHSolver::registryEntry()
{
  SolverEntry e{};
  e.type = PressureSolverType::WCSPH;
  e.key = "WCSPH";
  e.label = "WCSPH (Müller)";
  e.propertyValue = 0;
  e.kernel = DensityKernel::Poly6;
  e.defaultSupport = 2.0f;
  e.viscousOperator = ViscousOperator::MonaghanSpiky; // its viscous term uses the spiky kernel's gradient
  e.explicitLaminarViscosity = true;
  e.separateExtraViscosity = true;
  e.colourFieldSurfaceTension = true;
  e.holdsStrongCohesion = true;
  e.runoffCFLNumber = 0.1f;
  e.runsDistributed = true;
  e.create = [] { return std::unique_ptr<PressureSolver>(std::make_unique<WCSPHSolver>()); };
  e.stabilityAdvice = [](bool adaptive) -> std::string
  {
    return adaptive ? "lower CFLNumber or MaxTimeStep, or raise GasStiffness (a stiffer, less compressible "
                      "fluid) or Viscosity"
                    : "lower TimeStep or turn on AdaptiveTimeStep (the step must stay below the CFL limit of "
                      "the speed of sound sqrt(GasStiffness))";
  };
  return e;
}

void WCSPHSolver::start(SimulationParts& sim)
{
  this->computeDensityAndPressure(sim);
  sim.computeAccelerations(true);
}

double WCSPHSolver::signalSpeed(const SPHParameters& p) const
{
  return std::sqrt(static_cast<double>(p.gasStiffness));
}

double WCSPHSolver::step(SimulationParts& sim, double remaining)
{
  const double dt = sim.chooseTimeStep(remaining);
  const auto h = static_cast<float>(dt);
  sim.kick(0.5f * h);
  sim.drift(h);
  sim.sortByCell();
  this->computeDensityAndPressure(sim);
  sim.computeAccelerations(true);
  sim.kick(0.5f * h);
  sim.applyWallFriction(h);
  sim.statistics().timeStep = dt;
  sim.advanceTime(dt);
  return dt;
}

void WCSPHSolver::computeDensityAndPressure(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const Poly6Kernel w(p.smoothingLength);
  const float densityScale = p.particleMass * w.coefficient;
  const float k = p.gasStiffness;
  const float rho0 = p.restDensity;
  const bool clamp = p.clampNegativePressure;
  forEachParticleByCell(
    sim.grid(), s, p.smoothingLength, threadCount(p), {},
    [&](const CandidateBuffer& candidates, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      // The particle itself (r = 0) and, near walls, its images: the mirrored fluid fills
      // the cut-off neighbourhood, |x_i - R x_j| = |R x_i - x_j|.
      float sum = 0.0f;
      detail::forEachWallImage(position, position, p,
                               [&](const float* q, const float*, const float*, const float*, bool)
                               { sum += candidates.poly6Sum(q, w.h2); });
      const float rho = densityScale * sum;
      s.density[i] = rho;
      const float pressure = k * (rho - rho0);
      s.pressure[i] = clamp ? std::max(pressure, 0.0f) : pressure;
    },
    sim.ghostFlags()); // a ghost's density and pressure come from its owner
}
} // namespace parafluid::sph
