// The CUDA backend's entry point: the GPU simulation of the parameters' solver.
#include "cuda/CudaDeltaSimulation.cuh"
#include "cuda/CudaWCSPHSimulation.cuh"
#include "parafluid/sph/CudaBackend.h"

namespace parafluid::sph
{
std::unique_ptr<Simulation> makeCudaSimulation(const SPHParameters& parameters, ParticleState initial,
                                               std::shared_ptr<const TriangleBoundary> boundary)
{
  std::string reason;
  if (!cudaBackendUsable(&reason))
  {
    throw std::invalid_argument("SPH: Backend CUDA: " + reason + "; choose Backend CPU or Automatic");
  }
  const std::string lacking = cudaBackendLacks(parameters);
  if (!lacking.empty())
  {
    throw std::invalid_argument("SPH: Backend CUDA does not run " + lacking + " yet; choose Backend CPU");
  }
  if (parameters.pressureSolver == PressureSolverType::WCSPH)
  {
    return std::make_unique<cuda::CudaWCSPHSimulation>(parameters, std::move(initial), std::move(boundary));
  }
  return std::make_unique<cuda::CudaDeltaSimulation>(parameters, std::move(initial), std::move(boundary));
}
} // namespace parafluid::sph
