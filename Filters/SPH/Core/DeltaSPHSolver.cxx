// δ-SPH: see DeltaSPHSolver.h for the scheme and its sources; its passes are in DeltaSPH*.cxx.
#include "parafluid/sph/DeltaSPHSolver.h"

#include "private/DeltaSPHPairs.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"

#include <limits>

namespace parafluid::sph
{
SolverEntry DeltaSPHSolver::registryEntry()
{
  SolverEntry e{};
  e.type = PressureSolverType::DeltaSPH;
  e.key = "DeltaSPH";
  e.label = "δ-SPH";
  e.propertyValue = 2;
  e.kernel = DensityKernel::WendlandC2;
  e.defaultSupport = kDeltaSPHSupport;
  e.minimumSupport = kDeltaSPHSupport; // an input's narrower smoothing_length runs its waves fast
  e.viscousOperator = ViscousOperator::Morris;
  e.explicitLaminarViscosity = true;
  e.meshWallInSums = true;
  // Under a cloudburst the terrain in its sums makes its run marginal (docs/design-notes.md).
  e.meshWallInRunoff = false;
  e.particleShifting = true;
  e.holdsStrongCohesion = true;
  e.runoffCFLNumber = 0.1f; // at 0.2 its integrated density drifted up under a cloudburst
  e.runsDistributed = true;
  e.create = [] { return std::unique_ptr<PressureSolver>(std::make_unique<DeltaSPHSolver>()); };
  e.stabilityAdvice = [](bool adaptive) -> std::string
  {
    return adaptive ? "lower CFLNumber or MaxTimeStep, or raise SoundSpeed (a stiffer, less compressible "
                      "fluid) or ArtificialViscosity"
                    : "lower TimeStep or turn on AdaptiveTimeStep (the step must stay below the CFL limit of "
                      "the speed of sound SoundSpeed)";
  };
  return e;
}

void DeltaSPHSolver::permute(SimulationParts& sim, const std::vector<std::uint32_t>& order, std::vector<float>& scratch,
                             int threads)
{
  // Density is state here (it is integrated, not summed), so it moves with its particle.
  ParticleState& s = sim.state();
  for (auto* a : { &s.density, &this->DensityRate, &this->WallSum, &this->Fullness, &this->SlowDeparture })
  {
    if (a->size() == s.size())
    {
      detail::permute(*a, scratch, order, threads);
    }
  }
  this->CorrectionFresh = false; // summed again where the particles now are
}

void DeltaSPHSolver::resize(std::size_t n)
{
  // Added particles (SPHSolver::addParticles): full neighbourhoods until the next continuity pass
  // says otherwise, and a slow departure that start() takes from where they are.
  this->Fullness.resize(n, 1.0f);
  this->SlowDeparture.resize(n, std::numeric_limits<float>::quiet_NaN());
}

double DeltaSPHSolver::step(SimulationParts& sim, double remaining)
{
  // Störmer-Verlet with density as a position-like variable: velocity at the half step moves the
  // particles and then changes the density, and the new density gives the forces of the second
  // half-kick. Density and velocity are never updated from each other's old values at once (that
  // forward-Euler coupling of the acoustic oscillation grows without bound).
  const double dt = sim.chooseTimeStep(remaining);
  const auto h = static_cast<float>(dt);
  sim.kick(0.5f * h);
  sim.drift(h);
  sim.sortByCell();
  if (sim.parameters().particleShifting)
  {
    this->shiftParticles(sim, h);
    // The shift moved particles by up to 0.2 spacings, some out of their grid cells: sorted again
    // (which finds their mesh walls anew), the passes after it find every pair within the support.
    sim.sortByCell();
  }
  this->advanceDensity(sim, h);
  this->updatePressure(sim);
  this->computeAccelerations(sim);
  sim.kick(0.5f * h);
  sim.applyWallFriction(h);
  sim.statistics().timeStep = dt;
  sim.advanceTime(dt);
  return dt;
}
} // namespace parafluid::sph
