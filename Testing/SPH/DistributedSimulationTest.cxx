// The distributed simulation (DistributedSimulation.h) with its processes as threads: the same scene
// on 1, 2 and 3 processes against the serial CPU run (every solver that runs distributed, with and
// without a boundary mesh), migration over many steps, an empty process, an imbalanced start,
// additions and removals, and errors that every process reports together.
#include "parafluid/sph/DistributedSimulation.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/common/ThreadCommunicator.h"
#include "parafluid/common/TriangleBoundary.h"
#include "parafluid/sph/SolverRegistry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;

constexpr double kSpacing = 0.02; // [m]

/// A dam-break tank 0.6 x 0.1 x 0.4 m for `solver` at kSpacing with a fixed step.
SPHParameters tank(PressureSolverType solver)
{
  SPHParameters p;
  p.pressureSolver = solver;
  p.smoothingLength = defaultSmoothingLength(solverEntry(solver), kSpacing, 0.0);
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, 0.6f, 0, 0.1f, 0, 0.4f };
  p.adaptiveTimeStep = false;
  p.timeStep = 2e-4f;
  return p;
}

/// A column 0.2 m long, 0.1 m wide and `height` high against the tank's x = 0 wall.
ParticleState column(double height = 0.3, double z0 = 0.0)
{
  auto lattice = fillBoxWithLattice({ 0, 0.2, 0, 0.1, z0, z0 + height }, kSpacing);
  return ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
}

/// A floor sloping down towards +x, from 0.06 m at x = 0 to 0.02 m at x = 0.6, two triangles.
std::shared_ptr<TriangleBoundary> slopingFloor()
{
  auto z = [](float x) { return 0.06f - 0.04f * x / 0.6f; };
  return std::make_shared<TriangleBoundary>(
    std::vector<float>{ -0.1f, -0.1f, z(-0.1f), 0.7f, -0.1f, z(0.7f), 0.7f, 0.2f, z(0.7f), -0.1f, 0.2f, z(-0.1f) },
    std::vector<std::uint32_t>{ 0, 1, 2, 0, 2, 3 });
}

/// The particles `whole` gives process `rank` of `ranks`: every ranks-th, so each piece spans the
/// scene and the first hand-over moves most of them.
ParticleState pieceOf(const ParticleState& whole, int rank, int ranks)
{
  ParticleState piece;
  for (std::size_t i = static_cast<std::size_t>(rank); i < whole.size(); i += static_cast<std::size_t>(ranks))
  {
    piece.x.push_back(whole.x[i]);
    piece.y.push_back(whole.y[i]);
    piece.z.push_back(whole.z[i]);
    piece.vx.push_back(whole.vx[i]);
    piece.vy.push_back(whole.vy[i]);
    piece.vz.push_back(whole.vz[i]);
    piece.id.push_back(whole.id[i]);
    if (!whole.density.empty())
    {
      piece.density.push_back(whole.density[i]);
    }
  }
  return piece;
}

/// A particle's position [m] and its last acceleration [m/s^2].
struct Position
{
  float x, y, z;
  float ax, ay, az;
};

/// What each process of a run ended with, and the error each threw ("" when none).
struct RankResults
{
  std::vector<std::map<std::int64_t, Position>> particles;
  std::vector<std::string> errors;
  std::size_t total() const
  {
    std::size_t n = 0;
    for (const auto& m : particles)
    {
      n += m.size();
    }
    return n;
  }
};

std::map<std::int64_t, Position> byId(const ParticleState& s)
{
  std::map<std::int64_t, Position> out;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    out[s.id[i]] = { s.x[i], s.y[i], s.z[i], s.ax[i], s.ay[i], s.az[i] };
  }
  return out;
}

/// Runs `ranks` processes as threads: each makes its distributed simulation of `piece(rank)` and
/// calls `work` on it; returns each one's particles afterwards and what it threw.
RankResults runProcesses(int ranks, const SPHParameters& p, const std::function<ParticleState(int)>& piece,
                         const std::shared_ptr<const TriangleBoundary>& boundary,
                         const std::function<void(Simulation&, int)>& work)
{
  auto group = std::make_shared<ThreadGroup>(ranks);
  RankResults results;
  results.particles.resize(static_cast<std::size_t>(ranks));
  results.errors.resize(static_cast<std::size_t>(ranks));
  std::vector<std::thread> threads;
  for (int r = 0; r < ranks; ++r)
  {
    threads.emplace_back(
      [&, r]
      {
        ThreadCommunicator communicator(group, r);
        try
        {
          auto simulation = makeDistributedSimulation(p, piece(r), boundary, communicator);
          work(*simulation, r);
          results.particles[static_cast<std::size_t>(r)] = byId(simulation->hostState());
        }
        catch (const std::exception& e)
        {
          results.errors[static_cast<std::size_t>(r)] = e.what();
        }
      });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  return results;
}

void expectNoErrors(const RankResults& results)
{
  for (std::size_t r = 0; r < results.errors.size(); ++r)
  {
    EXPECT_EQ(results.errors[r], "") << "process " << r;
  }
}

/// The largest distance [m] between a particle of the processes and the same id in `serial`, and
/// the largest difference of their accelerations [m/s^2]; infinity when the id sets differ or an
/// id is on two processes.
std::pair<double, double> largestDeparture(const RankResults& results, const std::map<std::int64_t, Position>& serial)
{
  constexpr double infinite = std::numeric_limits<double>::infinity();
  if (results.total() != serial.size())
  {
    return { infinite, infinite };
  }
  double position = 0.0, acceleration = 0.0;
  for (const auto& particles : results.particles)
  {
    for (const auto& [id, q] : particles)
    {
      const auto it = serial.find(id);
      if (it == serial.end())
      {
        return { infinite, infinite };
      }
      const Position& e = it->second;
      position = std::max(position, std::hypot(double(q.x) - e.x, double(q.y) - e.y, double(q.z) - e.z));
      acceleration = std::max(acceleration, std::hypot(double(q.ax) - e.ax, double(q.ay) - e.ay, double(q.az) - e.az));
    }
  }
  return { position, acceleration };
}

std::vector<PressureSolverType> distributedSolvers()
{
  std::vector<PressureSolverType> out;
  for (const SolverEntry& entry : solverRegistry())
  {
    if (entry.runsDistributed)
    {
      out.push_back(entry.type);
    }
  }
  return out;
}

/// The state of `initial` after `duration` of the serial run: water in motion, whose pressure
/// forces a ghost layer's errors would change.
ParticleState inMotion(const SPHParameters& p, const ParticleState& initial,
                       const std::shared_ptr<const TriangleBoundary>& boundary, double duration)
{
  auto run = makeSimulation(p, initial, boundary, Backend::CPU);
  run->advance(duration);
  const ParticleState& s = run->hostState();
  ParticleState out;
  out.x = s.x;
  out.y = s.y;
  out.z = s.z;
  out.vx = s.vx;
  out.vy = s.vy;
  out.vz = s.vz;
  out.density = s.density;
  out.id = s.id;
  return out;
}

/// `start` set in motion for `settle` seconds, then `steps` fixed steps on 1, 2 and 3 processes
/// against the serial run.
void expectSameAsSerial(const SPHParameters& p, const ParticleState& start,
                        const std::shared_ptr<const TriangleBoundary>& boundary, double settle, int steps)
{
  const ParticleState initial = inMotion(p, start, boundary, settle);
  auto serial = makeSimulation(p, initial, boundary, Backend::CPU);
  const std::int64_t serialSteps = serial->advance(steps * p.timeStep);
  const auto expected = byId(serial->hostState());
  double largestAcceleration = 0.0;
  for (const auto& entry : expected)
  {
    const Position& e = entry.second;
    largestAcceleration = std::max(largestAcceleration, std::hypot(double(e.ax), double(e.ay), double(e.az)));
  }
  for (int ranks : { 1, 2, 3 })
  {
    const RankResults results = runProcesses(
      ranks, p, [&](int r) { return pieceOf(initial, r, ranks); }, boundary,
      [&](Simulation& s, int) { EXPECT_EQ(s.advance(steps * p.timeStep), serialSteps); });
    expectNoErrors(results);
    EXPECT_EQ(results.total(), initial.size()) << ranks << " processes";
    const auto [position, acceleration] = largestDeparture(results, expected);
    EXPECT_LT(position, 1e-5) << ranks << " processes, " << solverEntry(p.pressureSolver).key;
    // A ghost's stale value shows in its neighbours' forces long before it moves them a micrometre;
    // densities summed in another order change WCSPH's pressure, rho - rho0, by up to 4e-4 of the
    // largest acceleration (measured), a stale ghost density by over 1e-3.
    EXPECT_LT(acceleration, 1e-3 * largestAcceleration) << ranks << " processes, " << solverEntry(p.pressureSolver).key;
    for (const auto& particles : results.particles)
    {
      EXPECT_GT(particles.size(), initial.size() / (2 * ranks)) << "each process holds a share";
    }
  }
}

TEST(DistributedSimulation, EachSolverOnOneTwoAndThreeProcessesFollowsTheSerialRun)
{
  for (PressureSolverType solver : distributedSolvers())
  {
    expectSameAsSerial(tank(solver), column(), nullptr, 0.05, 20);
  }
}

TEST(DistributedSimulation, EachSolverOnAMeshFloorFollowsTheSerialRun)
{
  for (PressureSolverType solver : distributedSolvers())
  {
    expectSameAsSerial(tank(solver), column(0.2, 0.07), slopingFloor(), 0.12, 20); // on the floor
  }
}

TEST(DistributedSimulation, AfterAFifthOfASecondTheSurgeFrontAndCompressionMatchTheSerialRun)
{
  SPHParameters p = tank(PressureSolverType::DeltaSPH);
  p.adaptiveTimeStep = true;
  const ParticleState initial = column(0.2);
  const double duration = 0.2; // [s]
  auto serial = makeSimulation(p, initial, nullptr, Backend::CPU);
  serial->advance(duration);
  auto frontOf = [](const std::map<std::int64_t, Position>& particles)
  {
    float front = 0.0f;
    for (const auto& entry : particles)
    {
      front = std::max(front, entry.second.x);
    }
    return front;
  };
  const float serialFront = frontOf(byId(serial->hostState()));
  const double serialCompression = serial->lastStep().meanCompression;
  ASSERT_GT(serialFront, 0.3f) << "the dam broke";
  std::vector<double> compression(3, 0.0);
  const RankResults results = runProcesses(
    3, p, [&](int r) { return pieceOf(initial, r, 3); }, nullptr,
    [&](Simulation& s, int r)
    {
      s.advance(duration);
      compression[static_cast<std::size_t>(r)] = s.lastStep().meanCompression;
    });
  expectNoErrors(results);
  float front = 0.0f;
  for (const auto& particles : results.particles)
  {
    front = std::max(front, frontOf(particles));
  }
  EXPECT_NEAR(front, serialFront, 0.01 * serialFront);
  for (double c : compression)
  {
    EXPECT_NEAR(c, serialCompression, 0.01 * serialCompression + 1e-7) << "the mean is over all processes";
  }
}

TEST(DistributedSimulation, ParticlesSloshingAcrossTheSlabsForTwoThousandStepsAreNeitherLostNorDuplicated)
{
  SPHParameters p = tank(PressureSolverType::WCSPH);
  p.domainBounds = { 0, 0.3f, 0, 0.06f, 0, 0.3f };
  auto lattice = fillBoxWithLattice({ 0, 0.12, 0, 0.06, 0, 0.1 }, kSpacing);
  ParticleState initial = ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
  for (float& vx : initial.vx)
  {
    vx = 1.5f; // [m/s] the block runs into the far wall and back
  }
  std::vector<std::vector<std::int64_t>> firstOwned(3), migrated(3);
  const RankResults results = runProcesses(
    3, p, [&](int r) { return pieceOf(initial, r, 3); }, nullptr,
    [&](Simulation& s, int r)
    {
      for (const auto& entry : byId(s.hostState()))
      {
        firstOwned[static_cast<std::size_t>(r)].push_back(entry.first);
      }
      for (int k = 0; k < 20; ++k)
      {
        s.advance(100 * p.timeStep);
      }
      EXPECT_EQ(s.stepCount(), 2000);
    });
  expectNoErrors(results);
  ASSERT_EQ(results.total(), initial.size());
  std::map<std::int64_t, int> holders;
  std::size_t moved = 0;
  for (std::size_t r = 0; r < 3; ++r)
  {
    for (const auto& entry : results.particles[r])
    {
      ++holders[entry.first];
      const auto& first = firstOwned[r];
      moved += std::find(first.begin(), first.end(), entry.first) == first.end() ? 1 : 0;
    }
  }
  EXPECT_EQ(holders.size(), initial.size()) << "every id once";
  EXPECT_EQ(holders.begin()->first, 0);
  EXPECT_EQ(holders.rbegin()->first, static_cast<std::int64_t>(initial.size()) - 1);
  EXPECT_GT(moved, initial.size() / 10) << "particles changed process on the way";
}

TEST(DistributedSimulation, EverythingReadByOneProcessIsSharedOutAndAProcessWithoutParticlesTakesPart)
{
  const SPHParameters p = tank(PressureSolverType::DeltaSPH);
  const ParticleState initial = column();
  const RankResults results = runProcesses(
    3, p, [&](int r) { return r == 0 ? initial : ParticleState{}; }, nullptr,
    [&](Simulation& s, int) { s.advance(10 * p.timeStep); });
  expectNoErrors(results);
  ASSERT_EQ(results.total(), initial.size());
  for (const auto& particles : results.particles)
  {
    EXPECT_NEAR(double(particles.size()), initial.size() / 3.0, 0.2 * initial.size() / 3.0) << "balanced by count";
  }
  // Two particles among three processes: one of them owns none and still steps with the others.
  ParticleState pair = ParticleState::atRest({ 0.1f, 0.5f }, { 0.05f, 0.05f }, { 0.2f, 0.2f });
  const RankResults few = runProcesses(
    3, p, [&](int r) { return r == 2 ? pair : ParticleState{}; }, nullptr,
    [&](Simulation& s, int)
    {
      s.advance(30 * p.timeStep);
      EXPECT_NEAR(s.time(), 30 * p.timeStep, 1e-9);
    });
  expectNoErrors(few);
  EXPECT_EQ(few.total(), 2u);
  const RankResults none = runProcesses(
    2, p, [&](int) { return ParticleState{}; }, nullptr, [&](Simulation& s, int) { s.advance(5 * p.timeStep); });
  expectNoErrors(none);
  EXPECT_EQ(none.total(), 0u);
}

TEST(DistributedSimulation, AddedAndRemovedParticlesAreCountedOnceWithIdsAfterTheLargest)
{
  const SPHParameters p = tank(PressureSolverType::DeltaSPH);
  const ParticleState initial = column(0.2);
  std::vector<std::size_t> removedSeen(2, 0);
  const RankResults results = runProcesses(
    2, p, [&](int r) { return pieceOf(initial, r, 2); }, nullptr,
    [&](Simulation& s, int r)
    {
      s.advance(5 * p.timeStep);
      // Only process 1 adds: a row of drops above the column's far half, falling.
      std::vector<float> x, y, z, v0;
      if (r == 1)
      {
        for (int k = 0; k < 8; ++k)
        {
          x.push_back(0.02f + 0.04f * k);
          y.push_back(0.05f);
          z.push_back(0.35f);
          v0.push_back(0.0f);
        }
      }
      std::vector<float> vz(v0.size(), -1.0f);
      s.addParticles(x, y, z, v0, v0, vz);
      s.advance(5 * p.timeStep);
      // Each process removes its particles of the lowest layer (z = 0.01 m at the start).
      const ParticleState& state = s.hostState();
      std::vector<std::uint8_t> low(state.size(), 0);
      for (std::size_t i = 0; i < state.size(); ++i)
      {
        low[i] = state.z[i] < 0.02f ? 1 : 0;
      }
      removedSeen[static_cast<std::size_t>(r)] = s.removeParticles(low);
      s.advance(5 * p.timeStep);
    });
  expectNoErrors(results);
  std::size_t low = 0;
  for (std::size_t i = 0; i < initial.size(); ++i)
  {
    low += initial.z[i] < 0.02f ? 1 : 0;
  }
  ASSERT_GT(low, 0u);
  EXPECT_EQ(removedSeen[0] + removedSeen[1], low) << "the lowest layer barely moved in 10 steps";
  EXPECT_EQ(results.total(), initial.size() + 8 - low);
  std::map<std::int64_t, int> holders;
  for (const auto& particles : results.particles)
  {
    for (const auto& entry : particles)
    {
      EXPECT_EQ(++holders[entry.first], 1) << "id " << entry.first << " on two processes";
    }
  }
  const auto n = static_cast<std::int64_t>(initial.size());
  for (std::int64_t id = n; id < n + 8; ++id)
  {
    EXPECT_EQ(holders.count(id), 1u) << "the added particles' ids follow the largest";
  }
}

TEST(DistributedSimulation, RefusalsAndErrorsReachEveryProcess)
{
  const ParticleState initial = column(0.1);
  auto expectAllRefuse = [](const RankResults& results, const std::string& words)
  {
    for (std::size_t r = 0; r < results.errors.size(); ++r)
    {
      EXPECT_FALSE(results.errors[r].empty()) << "process " << r << " went on";
      if (r == 0)
      {
        EXPECT_NE(results.errors[r].find(words), std::string::npos) << results.errors[r];
      }
    }
  };
  auto nothing = [](Simulation&, int) {};
  // A solver without ghost refreshes, every axis periodic.
  SPHParameters dfsph = tank(PressureSolverType::DFSPH);
  EXPECT_NE(distributedRunLacks(dfsph), "");
  expectAllRefuse(runProcesses(
                    2, dfsph, [&](int r) { return pieceOf(initial, r, 2); }, nullptr, nothing),
                  "PressureSolver");
  SPHParameters periodic = tank(PressureSolverType::WCSPH);
  periodic.periodic = { true, true, true };
  expectAllRefuse(runProcesses(
                    2, periodic, [&](int r) { return pieceOf(initial, r, 2); }, nullptr, nothing),
                  "Periodic");
  // A NaN in one process's piece.
  const SPHParameters p = tank(PressureSolverType::WCSPH);
  const RankResults nan = runProcesses(
    3, p,
    [&](int r)
    {
      ParticleState piece = pieceOf(initial, r, 3);
      if (r == 2)
      {
        piece.y[1] = std::numeric_limits<float>::quiet_NaN();
      }
      return piece;
    },
    nullptr, nothing);
  for (const std::string& error : nan.errors)
  {
    EXPECT_FALSE(error.empty());
  }
  EXPECT_NE(nan.errors[2].find("finite"), std::string::npos) << nan.errors[2];
  // One process stops the advance: every process stops at the same step.
  std::vector<std::int64_t> steps(2, -1);
  const RankResults stopped = runProcesses(
    2, p, [&](int r) { return pieceOf(initial, r, 2); }, nullptr,
    [&](Simulation& s, int r)
    {
      int calls = 0;
      s.advance(200 * p.timeStep, [&](double) { return r == 0 || ++calls < 3; });
      steps[static_cast<std::size_t>(r)] = s.stepCount();
    });
  expectNoErrors(stopped);
  EXPECT_EQ(steps[0], steps[1]);
  EXPECT_GT(steps[0], 0);
  EXPECT_LT(steps[0], 200);
}

/// A process's communicator that fails on its own at its `failAt`-th exchange, before taking part
/// in it: as a failed allocation in a pass between two ghost refreshes would.
class FailingCommunicator final : public Communicator
{
public:
  FailingCommunicator(Communicator& inner, int failAt)
    : Inner(inner)
    , FailAt(failAt)
  {
  }
  int rank() const override { return this->Inner.rank(); }
  int size() const override { return this->Inner.size(); }
  std::vector<std::vector<std::uint8_t>> exchange(const std::vector<std::vector<std::uint8_t>>& sends) override
  {
    if (this->Armed && ++this->Calls == this->FailAt)
    {
      throw std::bad_alloc();
    }
    return this->Inner.exchange(sends);
  }
  void reduce(std::vector<double>& values, Reduction op) override { this->Inner.reduce(values, op); }
  void abandon() override { this->Inner.abandon(); }
  bool Armed = false;

private:
  Communicator& Inner;
  int FailAt;
  int Calls = 0;
};

TEST(DistributedSimulation, AProcessFailingInTheMiddleOfAStepStopsEveryProcess)
{
  const SPHParameters p = tank(PressureSolverType::DeltaSPH);
  const ParticleState initial = column(0.2);
  // Failing at the first, a middle and a late exchange of the steps: every process ends with an
  // error, none waits.
  for (const int failAt : { 1, 4, 23 })
  {
    auto group = std::make_shared<ThreadGroup>(3);
    std::vector<std::string> errors(3);
    std::vector<std::thread> threads;
    for (int r = 0; r < 3; ++r)
    {
      threads.emplace_back(
        [&, r]
        {
          ThreadCommunicator threads(group, r);
          FailingCommunicator communicator(threads, r == 1 ? failAt : -1);
          try
          {
            auto simulation = makeDistributedSimulation(p, pieceOf(initial, r, 3), nullptr, communicator);
            communicator.Armed = true;
            simulation->advance(40 * p.timeStep);
          }
          catch (const std::exception& e)
          {
            errors[static_cast<std::size_t>(r)] = e.what();
          }
        });
    }
    for (std::thread& t : threads)
    {
      t.join();
    }
    EXPECT_NE(errors[1].find("bad_alloc"), std::string::npos) << "at exchange " << failAt << ": " << errors[1];
    for (const int r : { 0, 2 })
    {
      EXPECT_NE(errors[static_cast<std::size_t>(r)].find("process 1 of 3 failed"), std::string::npos)
        << "process " << r << " at exchange " << failAt << ": " << errors[static_cast<std::size_t>(r)];
    }
  }
}
} // namespace
