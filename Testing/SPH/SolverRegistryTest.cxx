// The solver registry against itself and the plugin XML, and what every registered solver must do
// through the Simulation interface (parameterised over the registry: a new solver is tested here
// by adding its entry).
#include "parafluid/sph/SolverRegistry.h"
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/PressureSolver.h"
#include "parafluid/sph/Simulation.h"

#include "EverySolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace
{
using namespace parafluid;
using namespace parafluid::sph;

constexpr float kSpacing = 0.01f;

std::string readFile(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// value -> text of the enumeration of every `PressureSolver` property in one plugin XML.
std::vector<std::map<int, std::string>> pressureSolverEnumerations(const std::string& xml)
{
  std::vector<std::map<int, std::string>> found;
  const std::regex property(R"re(<IntVectorProperty\s+name="PressureSolver"[\s\S]*?</IntVectorProperty>)re");
  const std::regex entry(R"re(<Entry\s+value="(\d+)"\s+text="([^"]*)"\s*/>)re");
  for (auto p = std::sregex_iterator(xml.begin(), xml.end(), property); p != std::sregex_iterator(); ++p)
  {
    std::map<int, std::string> values;
    const std::string block = p->str();
    for (auto e = std::sregex_iterator(block.begin(), block.end(), entry); e != std::sregex_iterator(); ++e)
    {
      values[std::stoi((*e)[1])] = (*e)[2];
    }
    found.push_back(values);
  }
  return found;
}

SPHParameters waterFor(const SolverEntry& solver)
{
  SPHParameters p;
  p.pressureSolver = solver.type;
  p.smoothingLength = defaultSmoothingLength(solver, kSpacing, 0.0);
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  p.domainBounds = { 0, 0.2f, 0, 0.1f, 0, 0.2f };
  return p;
}

ParticleState block()
{
  auto lattice = fillBoxWithLattice({ 0, 0.08, 0, 0.05, 0, 0.08 }, kSpacing);
  return ParticleState::atRest(std::move(lattice.x), std::move(lattice.y), std::move(lattice.z));
}
} // namespace

TEST(SolverRegistry, EntriesAreDistinctAndComplete)
{
  std::set<std::string> keys, labels;
  std::set<int> values, types;
  for (const SolverEntry& e : solverRegistry())
  {
    EXPECT_TRUE(keys.insert(e.key).second) << e.key;
    EXPECT_TRUE(labels.insert(e.label).second) << e.label;
    EXPECT_TRUE(values.insert(e.propertyValue).second) << e.key;
    EXPECT_TRUE(types.insert(static_cast<int>(e.type)).second) << e.key;
    ASSERT_NE(e.create, nullptr) << e.key;
    ASSERT_NE(e.stabilityAdvice, nullptr) << e.key;
    EXPECT_NE(e.create(), nullptr) << e.key;
    EXPECT_GT(e.defaultSupport, 1.0f) << e.key;
    EXPECT_TRUE(e.maximumSupport == 0.0f || e.maximumSupport >= e.defaultSupport) << e.key;
    EXPECT_LE(e.minimumSupport, e.defaultSupport) << e.key;
    EXPECT_GT(e.runoffCFLNumber, 0.0f) << e.key;
    EXPECT_EQ(&solverEntry(e.type), &e);
    EXPECT_EQ(findSolver(e.key), &e);
    EXPECT_EQ(findSolver(e.label), &e);
    EXPECT_EQ(solverForPropertyValue(e.propertyValue), &e);
  }
  EXPECT_EQ(solverRegistry().size(), 3u);
  EXPECT_EQ(findSolver("no such solver"), nullptr);
  EXPECT_EQ(solverForPropertyValue(-1), nullptr);
  EXPECT_THROW(solverEntry(static_cast<PressureSolverType>(99)), std::invalid_argument);
  // The default parameters name a registered solver.
  EXPECT_NO_THROW(solverEntry(SPHParameters{}.pressureSolver));
}

TEST(SolverRegistry, PluginEnumerationsAreTheRegistry)
{
  // SPH Step's and the Rain filter's PressureSolver menus offer exactly the registry's solvers,
  // each under its label and property value (a saved state stores the value).
  std::map<int, std::string> expected;
  for (const SolverEntry& e : solverRegistry())
  {
    expected[e.propertyValue] = e.label;
  }
  int menus = 0;
  for (const char* file : { "ParaFluidSPH.xml", "ParaFluidRain.xml" })
  {
    const std::string xml = readFile(std::string(PARAFLUID_PLUGIN_XML_DIR) + "/" + file);
    ASSERT_FALSE(xml.empty()) << file;
    for (const auto& menu : pressureSolverEnumerations(xml))
    {
      EXPECT_EQ(menu, expected) << file;
      ++menus;
    }
  }
  EXPECT_EQ(menus, 2);
}

TEST(SolverRegistry, DefaultSmoothingLengthKeepsTheInputsAndWidensToTheMinimum)
{
  for (const SolverEntry& e : solverRegistry())
  {
    EXPECT_FLOAT_EQ(defaultSmoothingLength(e, 0.01, 0.0), e.defaultSupport * 0.01f) << e.key;
    EXPECT_FLOAT_EQ(defaultSmoothingLength(e, 0.01, 0.05), 0.05f) << e.key;
    EXPECT_FLOAT_EQ(defaultSmoothingLength(e, 0.01, 0.001), std::max(0.001f, e.minimumSupport * 0.01f)) << e.key;
  }
}

class EverySolver : public parafluid::testing::EverySolverTest
{
};

TEST_P(EverySolver, AdvancesThroughTheInterfaceToExactlyTheAskedTime)
{
  const SolverEntry& solver = GetParam();
  std::unique_ptr<Simulation> sim = makeSimulation(waterFor(solver), block(), nullptr, Backend::CPU);
  EXPECT_STREQ(sim->backendName(), "CPU");
  const std::size_t n = sim->particleCount();
  const double initialHeight = [&]
  {
    double z = 0.0;
    for (float v : sim->hostState().z)
    {
      z += v;
    }
    return z / static_cast<double>(n);
  }();
  const std::int64_t steps = sim->advance(0.03);
  EXPECT_GT(steps, 0);
  EXPECT_EQ(sim->stepCount(), steps);
  EXPECT_EQ(sim->time(), 0.03);
  ASSERT_EQ(sim->particleCount(), n);
  double z = 0.0;
  std::set<std::int64_t> ids;
  for (std::size_t i = 0; i < n; ++i)
  {
    const ParticleState& s = sim->hostState();
    ASSERT_TRUE(std::isfinite(s.x[i] + s.y[i] + s.z[i] + s.vx[i] + s.vy[i] + s.vz[i] + s.pressure[i])) << solver.key;
    z += s.z[i];
    ids.insert(s.id[i]);
  }
  EXPECT_EQ(ids.size(), n) << "every particle keeps its own id";
  // The block falls and spreads under gravity: its mean height drops.
  EXPECT_LT(z / static_cast<double>(n), initialHeight) << solver.key;
  EXPECT_GT(sim->bytesPerParticle(), 0.0);
  EXPECT_GT(sim->proposedTimeStep(), 0.0);
  EXPECT_EQ(sim->smoothedPressure().size(), n);
  EXPECT_EQ(sim->neighbourCounts().size(), n);
}

TEST_P(EverySolver, HandsOverTheParticlesThatLeftARegionAndTakesNewOnes)
{
  const SolverEntry& solver = GetParam();
  std::unique_ptr<Simulation> sim = makeSimulation(waterFor(solver), block());
  sim->advance(0.01);
  const std::size_t n = sim->particleCount();
  const std::array<double, 6> region = { 0.0, 0.045, -1.0, 1.0, -1.0, 1.0 };
  std::size_t outside = 0;
  for (float x : sim->hostState().x)
  {
    outside += x > region[1] ? 1 : 0;
  }
  ASSERT_GT(outside, 0u);
  const ParticleState leaving = sim->removeParticlesOutside(region);
  EXPECT_EQ(leaving.size(), outside);
  EXPECT_EQ(sim->particleCount(), n - outside);
  for (std::size_t i = 0; i < leaving.size(); ++i)
  {
    EXPECT_GT(leaving.x[i], region[1]);
  }
  for (float x : sim->hostState().x)
  {
    EXPECT_LE(x, region[1]);
  }
  // They come back (as another process would add them) and the run goes on.
  sim->addParticles(leaving.x, leaving.y, leaving.z, leaving.vx, leaving.vy, leaving.vz);
  EXPECT_EQ(sim->particleCount(), n);
  EXPECT_NO_THROW(sim->advance(0.01)) << solver.key;
  EXPECT_EQ(sim->removeParticlesOutside({ -1, 1, -1, 1, -1, 1 }).size(), 0u);
}

TEST_P(EverySolver, BlowUpAdviceNamesTheTimeStepProperties)
{
  const SolverEntry& solver = GetParam();
  for (bool adaptive : { true, false })
  {
    SPHParameters p = waterFor(solver);
    p.adaptiveTimeStep = adaptive;
    const std::string advice = makeSimulation(p, block())->stabilityAdvice();
    EXPECT_EQ(advice, solver.stabilityAdvice(adaptive));
    EXPECT_NE(advice.find(adaptive ? "CFLNumber" : "TimeStep"), std::string::npos) << solver.key << ": " << advice;
  }
}

TEST_P(EverySolver, RefusesASupportWiderThanItsLimit)
{
  const SolverEntry& solver = GetParam();
  SPHParameters p = waterFor(solver);
  p.smoothingLength = (solver.maximumSupport > 0.0f ? solver.maximumSupport + 0.5f : 4.0f) * kSpacing;
  p.particleMass = latticeParticleMass(kSpacing, p.smoothingLength, p.restDensity, p.densityKernel());
  const std::string problem = p.validate();
  if (solver.maximumSupport > 0.0f)
  {
    EXPECT_NE(problem.find("SmoothingLength"), std::string::npos) << solver.key << ": " << problem;
  }
  else
  {
    EXPECT_EQ(problem, "") << solver.key;
  }
}

PARAFLUID_FOR_EVERY_SOLVER(EverySolver);
