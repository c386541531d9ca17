// δ-SPH's slow-departure filter: the slow part of each particle's density departure from
// hydrostatic, which the density diffusion leaves alone near a free surface.
#include "parafluid/sph/DeltaSPHSolver.h"

#include "private/DeltaSPHPairs.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"

#include <limits>

namespace parafluid::sph
{
using detail::threadCount;
using namespace delta;

void DeltaSPHSolver::startSlowDeparture(SimulationParts& sim)
{
  // Kept across a restart (particles added: see resize); otherwise each particle's slow departure
  // starts at its departure, so the fluid as given counts as settled.
  const ParticleState& s = sim.state();
  const std::size_t n = s.size();
  if (this->Fullness.size() != n || this->SlowDeparture.size() != n)
  {
    this->Fullness.assign(n, 1.0f);
    this->SlowDeparture.assign(n, std::numeric_limits<float>::quiet_NaN());
  }
  const Constants k = makeConstants(sim.parameters(), this->SoundSpeed, sim.particleSpacing(),
                                    sim.laplacianCorrection(), this->PressureCorrection);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!std::isfinite(this->SlowDeparture[i]) || !(this->SlowDepartureTime > 0.0))
    {
      this->SlowDeparture[i] = this->SlowDepartureTime > 0.0 ? departureFromHydrostatic(k, s, i) : 0.0f;
    }
  }
}

void DeltaSPHSolver::followSlowDeparture(SimulationParts& sim, float dt)
{
  const SPHParameters& p = sim.parameters();
  if (!(p.densityDiffusion > 0.0f) || !(this->SlowDepartureTime > 0.0))
  {
    return; // nothing diffuses, or (no gravity) the slow part stays 0
  }
  const Constants k =
    makeConstants(p, this->SoundSpeed, sim.particleSpacing(), sim.laplacianCorrection(), this->PressureCorrection);
  const float follow = static_cast<float>(std::min(1.0, dt / this->SlowDepartureTime));
  const ParticleState& s = sim.state();
  const auto n = static_cast<std::int64_t>(s.size());
  float* slow = this->SlowDeparture.data();
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < n; ++i)
  {
    slow[i] += follow * (departureFromHydrostatic(k, s, static_cast<std::size_t>(i)) - slow[i]);
  }
}
} // namespace parafluid::sph
