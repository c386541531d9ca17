// What the CUDA backend runs of SPH Step's options (see CudaBackend.h); checked before any GPU call.
#include "parafluid/sph/CudaBackend.h"

namespace parafluid::sph
{
std::string cudaBackendLacks(const SPHParameters& p)
{
  // δ-SPH and WCSPH run with every option SPH Step offers them; DFSPH does not run yet.
  if (p.pressureSolver == PressureSolverType::DFSPH)
  {
    return "PressureSolver DFSPH";
  }
  return {};
}
} // namespace parafluid::sph
