// What the CUDA backend runs of SPH Step's options (see CudaBackend.h); checked before any GPU call.
#include "parafluid/sph/CudaBackend.h"

namespace parafluid::sph
{
std::string cudaBackendLacks(const SPHParameters& p)
{
  // δ-SPH runs with every option SPH Step offers it; the other solvers do not run yet.
  if (p.pressureSolver == PressureSolverType::DeltaSPH)
  {
    return {};
  }
  return std::string("PressureSolver ") + (p.pressureSolver == PressureSolverType::DFSPH ? "DFSPH" : "WCSPH");
}
} // namespace parafluid::sph
