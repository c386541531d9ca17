// What the CUDA backend runs of SPH Step's options (see CudaBackend.h); checked before any GPU call.
#include "parafluid/sph/CudaBackend.h"

#include <vector>

namespace parafluid::sph
{
std::string cudaBackendLacks(const SPHParameters& p)
{
  std::vector<std::string> lacking;
  if (p.pressureSolver != PressureSolverType::DeltaSPH)
  {
    lacking.emplace_back(std::string("PressureSolver ") +
                         (p.pressureSolver == PressureSolverType::DFSPH ? "DFSPH" : "WCSPH"));
  }
  if (p.surfaceTension > 0.0f)
  {
    lacking.emplace_back("SurfaceTension");
  }
  std::string text;
  for (const std::string& what : lacking)
  {
    text += (text.empty() ? "" : ", ") + what;
  }
  return text;
}
} // namespace parafluid::sph
