// Müller's WCSPH on the GPU as a Simulation (see CudaWCSPHSimulation.cuh).
#include "cuda/CudaWCSPHSimulation.cuh"

#include "parafluid/sph/TimeStepControl.h"
#include "parafluid/sph/WCSPHSolver.h"

namespace parafluid::sph::cuda
{
std::size_t CudaWCSPHSimulation::solverBytesPerParticle(const SPHParameters& p)
{
  return p.surfaceTension > 0.0f && p.surfaceTensionModel == SurfaceTensionModel::Akinci ? 3 * sizeof(float) : 0;
}

CudaWCSPHSimulation::CudaWCSPHSimulation(const SPHParameters& parameters, ParticleState initial,
                                         std::shared_ptr<const TriangleBoundary> boundary)
  : CudaSimulation(parameters, initial, std::move(boundary), solverBytesPerParticle(parameters))
{
  const SPHParameters& p = this->Parameters;
  const float h = p.smoothingLength;
  this->Density = { h * h, p.particleMass * Poly6Kernel(h).coefficient, p.gasStiffness, p.restDensity,
                    p.clampNegativePressure };
  this->Forces =
    detail::mullerConstants(p, true, latticeSpikyGradientCorrection(this->Spacing, h), this->LaplacianCorrection);
  this->Viscosity = p.viscosity > 0.0f || p.kinematicViscosity > 0.0f;
  this->ColourTension = p.surfaceTension > 0.0f && p.surfaceTensionModel == SurfaceTensionModel::ColourField;
  const bool curvature = p.surfaceTensionModel == SurfaceTensionModel::Akinci;
  if (p.surfaceTension > 0.0f && (curvature || p.surfaceTensionModel == SurfaceTensionModel::AkinciCohesion))
  {
    this->Tension =
      AkinciConstants<Poly6Kernel>{ detail::CohesionKernel(h), Poly6Kernel(h), h, p.particleMass, p.restDensity,
                                    detail::akinciGamma(p),    curvature };
  }
  this->begin(std::move(initial));
}

double CudaWCSPHSimulation::signalSpeed() const
{
  return WCSPHSolver().signalSpeed(this->Parameters);
}

void CudaWCSPHSimulation::prepare(ParticleState& s, Columns&)
{
  // The density is summed from the positions at the start; the upload only fills the array.
  s.density.assign(s.size(), this->Parameters.restDensity);
  if (this->Tension && this->Tension->curvature)
  {
    this->Normals.reserve(3 * static_cast<std::size_t>(s.size()));
  }
}

void CudaWCSPHSimulation::densityAndForces()
{
  const DeviceState a = this->state();
  launchMullerDensity(a, this->Grid, this->Walls, this->Density, this->Stream);
  launchMullerForces(a, this->Grid, this->Walls, this->Forces, this->Viscosity, this->ColourTension, this->Stream);
  if (this->Tension)
  {
    launchAkinciTension(a, this->Normals.data(), this->Grid, *this->Tension, this->Stream);
  }
}

void CudaWCSPHSimulation::startPasses()
{
  this->densityAndForces();
}

double CudaWCSPHSimulation::stepPasses(double remaining)
{
  // WCSPHSolver::step: kick, drift, sort, density and pressure, forces, kick.
  const double dt = timeStepFor(this->Parameters, this->proposedTimeStep(), remaining);
  const auto h = static_cast<float>(dt);
  this->kick(0.5f * h);
  this->drift(h);
  this->sortByCell();
  this->densityAndForces();
  this->kick(0.5f * h);
  this->applyWallFriction(h);
  return dt;
}
} // namespace parafluid::sph::cuda
