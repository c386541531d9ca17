// The CUDA backend's entry points in a build without it (no nvcc found, or PARAFLUID_CUDA=OFF).
#include "parafluid/sph/CudaBackend.h"

#include <stdexcept>

namespace parafluid::sph
{
namespace
{
constexpr const char* kNoCuda = "this build of ParaFluid has no CUDA backend (it was built without nvcc, or with "
                                "PARAFLUID_CUDA=OFF)";
}

bool cudaBackendUsable(std::string* reason)
{
  if (reason)
  {
    *reason = kNoCuda;
  }
  return false;
}

std::string cudaDeviceName()
{
  return {};
}

std::unique_ptr<Simulation> makeCudaSimulation(const SPHParameters&, ParticleState,
                                               std::shared_ptr<const TriangleBoundary>)
{
  throw std::invalid_argument(std::string("SPH: Backend CUDA: ") + kNoCuda + "; choose Backend CPU or Automatic");
}
} // namespace parafluid::sph
