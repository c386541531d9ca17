// Strong scaling of the distributed SPH run (DistributedSimulation.h) with its processes as threads:
// a δ-SPH dam break (block 1 x 1 x 2 of its width against a wall of a tank 4 wide) stepped by the
// serial CPU simulation and by 1, 2, 4 ... processes. Per process count: seconds per step, the
// speed-up over the serial run, the share of a step spent in the communicator (messages and
// reductions, waiting for the slowest process included), and the bytes each process sends per
// step with its slab's width.
//
//   ParaFluidDistributedBenchmark [particles=200000] [steps=30] [largest process count=2]
//                                 [threads per process=1]
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/ThreadCommunicator.h"
#include "parafluid/sph/DistributedSimulation.h"
#include "parafluid/sph/SolverRegistry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>
#include <vector>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// A Communicator that times the calls it passes on and counts the bytes this process sends.
class MeteredCommunicator final : public Communicator
{
public:
  explicit MeteredCommunicator(Communicator& inner)
    : Inner(inner)
  {
  }
  int rank() const override { return this->Inner.rank(); }
  int size() const override { return this->Inner.size(); }
  std::vector<std::vector<std::uint8_t>> exchange(const std::vector<std::vector<std::uint8_t>>& sends) override
  {
    const auto start = Clock::now();
    for (std::size_t r = 0; r < sends.size(); ++r)
    {
      this->BytesSent += static_cast<int>(r) == this->rank() ? 0.0 : static_cast<double>(sends[r].size());
    }
    auto received = this->Inner.exchange(sends);
    this->Seconds += seconds(start);
    return received;
  }
  void abandon() override { this->Inner.abandon(); }
  void reduce(std::vector<double>& values, Reduction op) override
  {
    const auto start = Clock::now();
    this->Inner.reduce(values, op);
    this->Seconds += seconds(start);
  }
  using Communicator::reduce;

  double Seconds = 0.0;
  double BytesSent = 0.0;

private:
  Communicator& Inner;
};

struct Scene
{
  SPHParameters parameters;
  ParticleState initial;
};

Scene damBreak(std::size_t particles, int threads)
{
  const double a = 0.5; // [m] the block's width
  const double d = a * std::cbrt(2.0 / static_cast<double>(particles));
  Scene scene;
  SPHParameters& p = scene.parameters;
  p.pressureSolver = PressureSolverType::DeltaSPH;
  p.smoothingLength = defaultSmoothingLength(solverEntry(p.pressureSolver), d, 0.0);
  p.particleMass = latticeParticleMass(static_cast<float>(d), p.smoothingLength, p.restDensity, p.densityKernel());
  p.adaptiveTimeStep = false;
  // CFL 0.2 of δ-SPH's sound speed, 10 sqrt(2 g 1 m) = 44 m/s.
  p.timeStep = static_cast<float>(0.2 * p.smoothingLength / 44.3);
  p.domainBounds = { 0.f, static_cast<float>(4 * a), 0.f, static_cast<float>(a), 0.f, static_cast<float>(3 * a) };
  p.threads = threads;
  auto lattice = fillBoxWithLattice({ 0, a, 0, a, 0, 2 * a }, d);
  scene.initial = ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
  return scene;
}

struct Measured
{
  double secondsPerStep = 0.0;
  double communicationShare = 0.0; // mean over the processes
  double bytesPerStep = 0.0;       // the most any process sent per step
};

Measured runDistributed(const Scene& scene, int ranks, int steps)
{
  auto group = std::make_shared<ThreadGroup>(ranks);
  std::vector<double> busy(static_cast<std::size_t>(ranks)), sent(static_cast<std::size_t>(ranks));
  double wall = 0.0;
  std::vector<std::thread> threads;
  for (int r = 0; r < ranks; ++r)
  {
    threads.emplace_back(
      [&, r]
      {
        ThreadCommunicator plain(group, r);
        MeteredCommunicator metered(plain);
        // Process 0 holds the whole scene at the start, as a reader that did not split it would.
        auto simulation =
          makeDistributedSimulation(scene.parameters, r == 0 ? scene.initial : ParticleState{}, nullptr, metered);
        simulation->advance(10 * scene.parameters.timeStep); // leave the lattice
        metered.Seconds = 0.0;
        metered.BytesSent = 0.0;
        const auto start = Clock::now();
        simulation->advance(steps * scene.parameters.timeStep);
        const double elapsed = seconds(start);
        busy[static_cast<std::size_t>(r)] = metered.Seconds / elapsed;
        sent[static_cast<std::size_t>(r)] = metered.BytesSent / steps;
        if (r == 0)
        {
          wall = elapsed;
        }
      });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  Measured m;
  m.secondsPerStep = wall / steps;
  for (double b : busy)
  {
    m.communicationShare += b / ranks;
  }
  m.bytesPerStep = *std::max_element(sent.begin(), sent.end());
  return m;
}

double runSerial(const Scene& scene, int steps)
{
  auto simulation = makeSimulation(scene.parameters, scene.initial, nullptr, Backend::CPU);
  simulation->advance(10 * scene.parameters.timeStep);
  const auto start = Clock::now();
  simulation->advance(steps * scene.parameters.timeStep);
  return seconds(start) / steps;
}
} // namespace

int main(int argc, char** argv)
{
  const std::size_t particles = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 200000;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 30;
  const int largest = argc > 3 ? std::atoi(argv[3]) : 2;
  const int threads = argc > 4 ? std::atoi(argv[4]) : 1;
  const Scene scene = damBreak(particles, threads);
  const double serial = runSerial(scene, steps);
  std::printf("δ-SPH dam break, %zu particles, %d steps, %d thread(s) per process, %u hardware threads\n",
              scene.initial.size(), steps, threads, std::thread::hardware_concurrency());
  std::printf("serial: %.4f s/step, %.3g particle-steps/s\n", serial, scene.initial.size() / serial);
  std::printf("%9s %10s %9s %14s %16s %14s\n", "processes", "s/step", "speed-up", "communication", "sent/step [MB]",
              "slab width [h]");
  const double width = scene.parameters.domainBounds[1] - scene.parameters.domainBounds[0];
  for (int ranks = 1; ranks <= largest; ranks *= 2)
  {
    const Measured m = runDistributed(scene, ranks, steps);
    // The block spreads along x in these steps little: its slabs share its 0.5 m.
    const double slab = std::min(0.5, width) / ranks / scene.parameters.smoothingLength;
    std::printf("%9d %10.4f %9.2f %13.1f%% %16.3f %14.1f\n", ranks, m.secondsPerStep, serial / m.secondsPerStep,
                100.0 * m.communicationShare, m.bytesPerStep / 1e6, slab);
  }
  return 0;
}
