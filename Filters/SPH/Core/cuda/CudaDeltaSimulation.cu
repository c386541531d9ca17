// δ-SPH on the GPU as a Simulation (see CudaDeltaSimulation.cuh).
#include "cuda/CudaDeltaSimulation.cuh"

#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/TimeStepControl.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parafluid::sph::cuda
{
CudaDeltaSimulation::CudaDeltaSimulation(const SPHParameters& parameters, ParticleState initial,
                                         std::shared_ptr<const TriangleBoundary> boundary)
  : CudaSimulation(parameters, initial, std::move(boundary), kSolverBytesPerParticle)
  , K(parameters.smoothingLength)
{
  const SPHParameters& p = this->Parameters;
  this->PressureCorrection = latticeGradientCorrection(this->Spacing, p.smoothingLength, p.densityKernel());
  if (p.surfaceTension > 0.0f)
  {
    this->Tension = AkinciConstants<WendlandC2Kernel>{ detail::CohesionKernel(p.smoothingLength),
                                                       WendlandC2Kernel(p.smoothingLength),
                                                       p.smoothingLength,
                                                       p.particleMass,
                                                       p.restDensity,
                                                       detail::akinciGamma(p),
                                                       p.surfaceTensionModel == SurfaceTensionModel::Akinci };
  }
  this->begin(std::move(initial));
}

DeltaArrays CudaDeltaSimulation::arrays() const
{
  DeltaArrays a;
  static_cast<DeviceState&>(a) = this->state();
  a.rate = this->Rate.data();
  a.fullness = this->Fullness.data();
  a.nextFullness = this->NextFullness.data();
  a.slow = this->Slow.data();
  a.correction = this->Parameters.gradientCorrection ? this->Correction.data() : nullptr;
  a.push = this->Push.data();
  a.interior = this->Interior.data();
  return a;
}

std::vector<float> CudaDeltaSimulation::newParticleColumns() const
{
  // A full neighbourhood until the next continuity pass says otherwise, and a slow departure the
  // start takes from where the particle is (DeltaSPHSolver::resize).
  return { 1.0f, std::numeric_limits<float>::quiet_NaN() };
}

void CudaDeltaSimulation::prepare(ParticleState& s, Columns& columns)
{
  const SPHParameters& p = this->Parameters;
  const std::size_t n = s.size();
  this->SoundSpeed = DeltaSPHSolver::automaticSoundSpeed(p, s);
  this->SlowDepartureTime = DeltaSPHSolver::slowDepartureTime(p, s);
  this->K =
    delta::makeConstants(p, this->SoundSpeed, this->Spacing, this->LaplacianCorrection, this->PressureCorrection);
  const bool given = s.density.size() == n && std::all_of(s.density.begin(), s.density.end(),
                                                          [](float rho) { return std::isfinite(rho) && rho > 0.0f; });
  if (!given)
  {
    s.density.assign(n, p.restDensity);
    DeltaSPHSolver::hydrostaticDensity(p, this->SoundSpeed, this->Spacing, s);
  }
  std::vector<float>& slow = columns[SLOW];
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!std::isfinite(slow[i]) || !(this->SlowDepartureTime > 0.0))
    {
      slow[i] = this->SlowDepartureTime > 0.0 ? delta::departureFromHydrostatic(this->K, s, i) : 0.0f;
    }
  }
  this->Fullness.upload(columns[FULLNESS].data(), n, this->Stream);
  this->Slow.upload(slow.data(), n, this->Stream);
  for (auto* buffer : { &this->Rate, &this->NextFullness, &this->Interior })
  {
    buffer->reserve(n);
  }
  this->Push.reserve(3 * n);
  if (p.gradientCorrection)
  {
    this->Correction.reserve(6 * n);
  }
  if (n > 0)
  {
    check(cudaMemsetAsync(this->Rate.data(), 0, n * sizeof(float), this->Stream), "clearing an array");
  }
}

void CudaDeltaSimulation::startPasses()
{
  const SPHParameters& p = this->Parameters;
  if (this->MeshWall)
  {
    launchStartWallSums(this->state().wall, this->N, this->Stream); // density counts from where each particle starts
  }
  const DeltaArrays a = this->arrays();
  const auto bulk = static_cast<float>(this->SoundSpeed * this->SoundSpeed * p.restDensity / delta::kGamma);
  launchIntegrateDensity(a, this->K, 0.0f, 0.0f, bulk, this->Stream); // the pressure from the start's density
  launchContinuity(a, this->Grid, this->Walls, this->K, this->Stream);
  this->Fullness.swap(this->NextFullness);
  this->accelerations();
}

void CudaDeltaSimulation::accelerations()
{
  const SPHParameters& p = this->Parameters;
  const DeltaArrays a = this->arrays();
  launchForces(a, this->Grid, this->Walls, this->K, p.kinematicViscosity > 0.0f || p.viscosity > 0.0f, this->Stream);
  if (this->Tension)
  {
    launchAkinciTension(a, a.push, this->Grid, *this->Tension, this->Stream); // the force pass has read the push
  }
}

double CudaDeltaSimulation::stepPasses(double remaining)
{
  // DeltaSPHSolver::step: kick, drift, sort, density (continuity), pressure, forces, kick.
  const SPHParameters& p = this->Parameters;
  const double dt = timeStepFor(p, this->proposedTimeStep(), remaining);
  const auto h = static_cast<float>(dt);
  const cudaStream_t stream = this->Stream;
  this->kick(0.5f * h);
  this->drift(h);
  this->sortByCell();
  if (p.particleShifting)
  {
    // As the CPU's step: shifted by the speeds of now, then sorted again (finding the mesh walls anew).
    launchMeasure(this->state(), p.restDensity, 0.0f, this->Partials.data(), this->Result.data(), stream);
    ShiftConstants shift;
    shift.inverseWSpacing = 1.0f / this->K.w.value(std::min(this->Spacing, 0.99f * p.smoothingLength));
    shift.volume = p.particleMass / p.restDensity;
    shift.limit = 0.2f * this->Spacing;
    shift.margin = 0.01f * this->Spacing;
    shift.twiceSupportDt = 2.0f * p.smoothingLength * h;
    launchShift(this->arrays(), this->Grid, this->Walls, this->K, shift, this->Result.data(), stream);
    this->sortByCell();
  }
  launchContinuity(this->arrays(), this->Grid, this->Walls, this->K, stream);
  this->Fullness.swap(this->NextFullness);
  const float follow = p.densityDiffusion > 0.0f && this->SlowDepartureTime > 0.0
                         ? static_cast<float>(std::min(1.0, h / this->SlowDepartureTime))
                         : 0.0f;
  const auto bulk = static_cast<float>(this->SoundSpeed * this->SoundSpeed * p.restDensity / delta::kGamma);
  launchIntegrateDensity(this->arrays(), this->K, h, follow, bulk, stream);
  this->accelerations();
  this->kick(0.5f * h);
  this->applyWallFriction(h);
  return dt;
}

CudaSimulation::Columns CudaDeltaSimulation::downloadColumns() const
{
  Columns columns(2, std::vector<float>(this->N));
  this->Fullness.download(columns[FULLNESS].data(), this->N, this->Stream);
  this->Slow.download(columns[SLOW].data(), this->N, this->Stream);
  check(cudaStreamSynchronize(this->Stream), "copying the solver's state from the GPU");
  return columns;
}

std::vector<DeviceBuffer<float>*> CudaDeltaSimulation::sortedSolverArrays()
{
  return { &this->Fullness, &this->Slow };
}

std::vector<DeviceBuffer<float>*> CudaDeltaSimulation::solverArrays()
{
  return { &this->Rate,       &this->Fullness, &this->NextFullness, &this->Slow,
           &this->Correction, &this->Push,     &this->Interior };
}
} // namespace parafluid::sph::cuda
