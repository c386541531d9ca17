#include "parafluid/sph/Simulation.h"

#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/CudaBackend.h"
#include "parafluid/sph/SPHSolver.h"

#include <stdexcept>

namespace parafluid::sph
{
namespace
{
using FloatArray = std::vector<float> ParticleState::*;
constexpr FloatArray kFloatArrays[] = { &ParticleState::x,       &ParticleState::y,       &ParticleState::z,
                                        &ParticleState::vx,      &ParticleState::vy,      &ParticleState::vz,
                                        &ParticleState::ax,      &ParticleState::ay,      &ParticleState::az,
                                        &ParticleState::density, &ParticleState::pressure };
} // namespace

ParticleState Simulation::removeParticlesOutside(const std::array<double, 6>& region)
{
  const ParticleState& s = this->hostState();
  const std::size_t n = s.size();
  std::vector<std::uint8_t> leaving(n, 0);
  ParticleState out;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double p[3] = { s.x[i], s.y[i], s.z[i] };
    bool inside = true;
    for (int a = 0; a < 3; ++a)
    {
      inside = inside && p[a] >= region[2 * a] && p[a] <= region[2 * a + 1];
    }
    if (inside)
    {
      continue;
    }
    leaving[i] = 1;
    for (auto array : kFloatArrays)
    {
      (out.*array).push_back((s.*array)[i]);
    }
    out.id.push_back(s.id[i]);
    out.originalIndex.push_back(s.originalIndex[i]);
  }
  if (!out.x.empty())
  {
    this->removeParticles(leaving);
  }
  return out;
}

std::unique_ptr<Simulation> makeSimulation(const SPHParameters& parameters, ParticleState initial,
                                           std::shared_ptr<const TriangleBoundary> boundary, Backend backend,
                                           std::string* choice)
{
  auto onCpu = [&](const std::string& why)
  {
    if (choice)
    {
      *choice = "CPU" + (why.empty() ? std::string() : ": " + why);
    }
    return std::make_unique<SPHSolver>(parameters, std::move(initial), std::move(boundary));
  };
  if (backend == Backend::CPU)
  {
    return onCpu("");
  }
  std::string unusable;
  const bool usable = cudaBackendUsable(&unusable);
  const std::string lacking = cudaBackendLacks(parameters);
  if (backend == Backend::CUDA)
  {
    if (!usable)
    {
      throw std::invalid_argument("SPH: Backend CUDA: " + unusable + "; choose Backend CPU or Automatic");
    }
    if (!lacking.empty())
    {
      throw std::invalid_argument("SPH: Backend CUDA does not run " + lacking +
                                  " yet; choose Backend CPU or Automatic (which runs such a scene on the CPU)");
    }
  }
  else if (!usable)
  {
    return onCpu(unusable);
  }
  else if (!lacking.empty())
  {
    return onCpu("the CUDA backend does not run " + lacking + " yet");
  }
  if (choice)
  {
    *choice = "CUDA (" + cudaDeviceName() + ")";
  }
  return makeCudaSimulation(parameters, std::move(initial), std::move(boundary));
}
} // namespace parafluid::sph
