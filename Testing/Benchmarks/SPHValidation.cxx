// Run time against error for the two pressure solvers on two scenes with known answers:
//  - hydrostatic: a column at rest; pressure against rho0 g depth (relative L2 error);
//  - dam break: a column of width a and height 2a released at t = 0; surge front Z = x/a against
//    T = t sqrt(2 g / a), compared with Martin & Moyce (1952).
// Writes CSV files into the directory given as first argument; plot_validation.py draws them.
// Usage: ParaFluidSPHValidation <output-directory> [--quick] [--scene all|hydrostatic|dambreak]
//        [--solver WCSPH|DFSPH] [--resolutions 10,20,40] [--viscosity 3.5] [--tolerance 0.001]
//        [--cfl 0.2] [--max-dt 0.005] [--stiffness 1000] [--width 0.05715]
//        [--walls log-law|free-slip|no-slip]
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace parafluid;
using namespace parafluid;
using namespace parafluid::sph;

namespace
{
constexpr float kGravity = 9.81f; // [m/s^2]
constexpr float kRho0 = 1000.0f;  // [kg/m^3]

const char* name(PressureSolverType s)
{
  return s == PressureSolverType::DFSPH ? "DFSPH" : s == PressureSolverType::DeltaSPH ? "DeltaSPH" : "WCSPH";
}

/// Water with h = 2 spacings; a slab four particles thick in y between free-slip mirror walls,
/// which makes the flow two-dimensional as in the experiments.
float gViscosity = 0.0f;                          // [Pa s], --viscosity; Müller's extra viscosity (3.5 in his paper)
float gDensityTolerance = 0.001f;                 // --tolerance; the filter's default (0.1 %)
float gGasStiffness = 1000.0f;                    // --stiffness [m^2/s^2], WCSPH's k (c = sqrt(k))
float gCFLNumber = SPHParameters().cflNumber;     // --cfl; smaller for a time-step convergence study
float gMaxTimeStep = SPHParameters().maxTimeStep; // --max-dt [s]
// --width a [m]: Martin & Moyce's column, 2.25 in. The size matters, not only the dimensionless
// form: the default viscosity (3.5 Pa s, an artificial one) sets a Reynolds number that grows as
// a^1.5, so a column of another size is a different flow from the experiment's.
float gColumnWidth = 0.05715f;
// --walls free-slip|no-slip|log-law: the tank's floor and end walls; the experiment's were smooth
// glass under water, whose boundary layer the law of the wall models (see TurbulentWallLaw.h).
WallFriction gWallFriction = WallFriction::LogLaw;

SPHParameters water(PressureSolverType solver, float spacing, const std::array<float, 6>& domain)
{
  SPHParameters p;
  p.pressureSolver = solver;
  p.smoothingLength = 2.0f * spacing;
  p.restDensity = kRho0;
  p.gasStiffness = gGasStiffness; // default 1000: c = 31.6 m/s, ten times the fastest flow here
  p.viscosity = gViscosity;
  p.gravity = { 0.0f, 0.0f, -kGravity };
  p.domainBounds = domain;
  // The y walls stay free-slip in every scene: they are the symmetry planes of a two-dimensional slab.
  p.wallFriction = gWallFriction;
  p.frictionWalls = { true, true, false, false, true, true };
  p.densityTolerance = gDensityTolerance;
  p.cflNumber = gCFLNumber;
  p.maxTimeStep = gMaxTimeStep;
  p.particleMass = latticeParticleMass(spacing, p.smoothingLength, kRho0, p.densityKernel());
  return p;
}

ParticleState lattice(const std::array<double, 6>& box, double spacing)
{
  auto l = fillBoxWithLattice(box, spacing);
  return ParticleState::atRest(std::move(l.x), std::move(l.y), std::move(l.z));
}

double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

struct Hydrostatic
{
  double error = 0.0, profileError = 0.0, wall = 0.0, compression = 0.0;
  long long particles = 0, steps = 0;
};

/// Column of width and height 0.2 m, `across` particles wide. Settles for 0.4 s, then pressure is
/// averaged over 20 samples 0.005 s apart (WCSPH's pressure rings acoustically with a period of
/// about 4 H / c = 0.025 s) and compared with rho0 g (H - z).
Hydrostatic hydrostatic(PressureSolverType solver, int across, std::ofstream* profile)
{
  const float width = 0.2f, height = 0.2f;
  const float d = width / static_cast<float>(across);
  const std::array<float, 6> domain = { 0.0f, width, 0.0f, 4 * d, 0.0f, 2.0f * height };
  SPHParameters p = water(solver, d, domain);
  SPHSolver s(p, lattice({ 0, width, 0, 4 * d, 0, height }, d));
  Hydrostatic r;
  r.particles = static_cast<long long>(s.state().size());
  const auto start = std::chrono::steady_clock::now();
  r.steps += s.advance(0.4);
  const std::size_t n = s.state().size();
  std::vector<double> sum(n, 0.0); // by id: the state is reordered every step
  const int samples = 40;
  for (int k = 0; k < samples; ++k)
  {
    r.steps += s.advance(0.005);
    r.compression += s.lastStep().meanCompression / samples;
    const std::vector<float> pressure = s.smoothedPressure(); // what SPH Step outputs as "pressure"
    for (std::size_t i = 0; i < n; ++i)
    {
      sum[static_cast<std::size_t>(s.state().id[i])] += pressure[i] / samples;
    }
  }
  r.wall = seconds(start);
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto id = static_cast<std::size_t>(s.state().id[i]);
    const double reference = kRho0 * kGravity * (height - s.state().z[i]);
    num += (sum[id] - reference) * (sum[id] - reference);
    den += reference * reference;
    if (profile)
    {
      *profile << name(solver) << "," << across << "," << s.state().z[i] << "," << sum[id] << "," << reference << "\n";
    }
  }
  r.error = std::sqrt(num / den);
  // The pressure-against-depth profile: particles binned into layers one spacing thick.
  std::vector<double> layerPressure(2 * static_cast<std::size_t>(across) + 2, 0.0),
    layerReference(layerPressure.size(), 0.0);
  std::vector<int> layerCount(layerPressure.size(), 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto id = static_cast<std::size_t>(s.state().id[i]);
    const auto layer = std::min(layerPressure.size() - 1, static_cast<std::size_t>(std::max(0.0f, s.state().z[i] / d)));
    layerPressure[layer] += sum[id];
    layerReference[layer] += kRho0 * kGravity * (height - s.state().z[i]);
    ++layerCount[layer];
  }
  num = den = 0.0;
  for (std::size_t l = 0; l < layerPressure.size(); ++l)
  {
    if (layerCount[l] > 0)
    {
      const double p = layerPressure[l] / layerCount[l], ref = layerReference[l] / layerCount[l];
      num += (p - ref) * (p - ref);
      den += ref * ref;
    }
  }
  r.profileError = std::sqrt(num / den);
  return r;
}

// Martin & Moyce (1952), column a = 2.25 in, n^2 = 2 (height 2a): T = t sqrt(2g/a), Z = x/a.
const double kExperimentT[] = {
  0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98, 3.11, 3.33
};
const double kExperimentZ[] = {
  1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67, 3.89, 4.11
};

struct DamBreak
{
  double meanError = 0.0, maxError = 0.0, wall = 0.0, meanCompression = 0.0, maxCompression = 0.0;
  long long particles = 0, steps = 0;
  double densityIterations = 0.0, divergenceIterations = 0.0;
};

/// Column a wide (--width) and 2a high in a tank 6a long. The front is the largest x of any particle
/// plus half a spacing (the edge of the particle's share of volume).
DamBreak damBreak(PressureSolverType solver, int across, double endT, std::ofstream& curve)
{
  const float a = gColumnWidth;
  const float d = a / static_cast<float>(across);
  const std::array<float, 6> domain = { 0.0f, 6.0f * a, 0.0f, 4 * d, 0.0f, 3.0f * a };
  SPHParameters p = water(solver, d, domain);
  SPHSolver s(p, lattice({ 0, a, 0, 4 * d, 0, 2 * a }, d));
  DamBreak r;
  r.particles = static_cast<long long>(s.state().size());
  const double timeScale = std::sqrt(2.0 * kGravity / a); // T = t * timeScale
  const double dT = 0.05;
  std::vector<double> T = { 0.0 }, Z;
  auto front = [&]() { return (*std::max_element(s.state().x.begin(), s.state().x.end()) + 0.5 * d) / a; };
  Z.push_back(front());
  long long compressionSamples = 0;
  const auto start = std::chrono::steady_clock::now();
  while (T.back() < endT - 1e-9)
  {
    // Step by hand (advance() would do the same) to record every step's statistics.
    const double end = s.time() + dT / timeScale;
    while (s.time() < end)
    {
      const double remaining = end - s.time();
      const double dt = s.step(remaining);
      ++r.steps;
      r.meanCompression += s.lastStep().meanCompression;
      r.maxCompression = std::max(r.maxCompression, s.lastStep().meanCompression);
      r.densityIterations += s.lastStep().densityIterations;
      r.divergenceIterations += s.lastStep().divergenceIterations;
      ++compressionSamples;
      if (dt >= remaining)
      {
        break;
      }
    }
    T.push_back(T.back() + dT);
    Z.push_back(front());
    curve << name(solver) << "," << across << "," << T.back() << "," << Z.back()
          << std::endl; // long runs: keep what is done
  }
  r.wall = seconds(start);
  r.meanCompression /= std::max(1LL, compressionSamples);
  r.densityIterations /= std::max(1LL, compressionSamples);
  r.divergenceIterations /= std::max(1LL, compressionSamples);
  // Relative error of the simulated front at each experimental time T <= 2.5 (linear interpolation).
  int count = 0;
  for (std::size_t e = 0; e < sizeof(kExperimentT) / sizeof(double); ++e)
  {
    if (kExperimentT[e] > 2.5 || kExperimentT[e] > T.back())
    {
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(kExperimentT[e] / dT);
    const double f = (kExperimentT[e] - T[k]) / dT;
    const double z = Z[k] + f * (Z[k + 1] - Z[k]);
    const double error = std::fabs(z - kExperimentZ[e]) / kExperimentZ[e];
    r.meanError += error;
    r.maxError = std::max(r.maxError, error);
    ++count;
  }
  r.meanError /= std::max(1, count);
  return r;
}
const char* const kUsage =
  "usage: ParaFluidSPHValidation <output-directory> [--quick] [--scene all|hydrostatic|dambreak]\n"
  "         [--solver WCSPH|DFSPH] [--resolutions 10,20,40] [--viscosity 3.5] [--tolerance 0.001]\n"
  "         [--cfl 0.2] [--max-dt 0.005] [--stiffness 1000] [--width 0.05715]\n"
  "         [--walls log-law|free-slip|no-slip]\n";
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << kUsage;
    return 2;
  }
  const std::string dir = argv[1];
  bool quick = false;
  std::string scene = "all";
  std::vector<PressureSolverType> solvers = { PressureSolverType::WCSPH, PressureSolverType::DFSPH,
                                              PressureSolverType::DeltaSPH };
  std::vector<int> resolutions;
  for (int k = 2; k < argc; ++k)
  {
    const std::string option = argv[k];
    if (option == "--quick")
    {
      quick = true;
    }
    else if (option == "--viscosity" && k + 1 < argc)
    {
      gViscosity = std::stof(argv[++k]);
    }
    else if (option == "--stiffness" && k + 1 < argc)
    {
      gGasStiffness = std::stof(argv[++k]);
    }
    else if (option == "--cfl" && k + 1 < argc)
    {
      gCFLNumber = std::stof(argv[++k]);
    }
    else if (option == "--max-dt" && k + 1 < argc)
    {
      gMaxTimeStep = std::stof(argv[++k]);
    }
    else if (option == "--width" && k + 1 < argc)
    {
      gColumnWidth = std::stof(argv[++k]);
    }
    else if (option == "--walls" && k + 1 < argc)
    {
      const std::string v = argv[++k];
      if (v != "free-slip" && v != "no-slip" && v != "log-law")
      {
        std::cerr << "--walls takes free-slip, no-slip or log-law\n";
        return 2;
      }
      gWallFriction = v == "free-slip" ? WallFriction::FreeSlip
                      : v == "no-slip" ? WallFriction::NoSlip
                                       : WallFriction::LogLaw;
    }
    else if (option == "--tolerance" && k + 1 < argc)
    {
      gDensityTolerance = std::stof(argv[++k]);
    }
    else if (option == "--scene" && k + 1 < argc)
    {
      scene = argv[++k];
    }
    else if (option == "--solver" && k + 1 < argc)
    {
      const std::string v = argv[++k];
      solvers = { v == "DFSPH" ? PressureSolverType::DFSPH : v == "DeltaSPH" ? PressureSolverType::DeltaSPH : PressureSolverType::WCSPH };
    }
    else if (option == "--resolutions" && k + 1 < argc)
    {
      resolutions.clear();
      for (const char* c = argv[++k]; *c;)
      {
        char* end = nullptr;
        resolutions.push_back(static_cast<int>(std::strtol(c, &end, 10)));
        c = *end == ',' ? end + 1 : end;
      }
    }
    else
    {
      std::cerr << "unknown option " << option << "\n" << kUsage;
      return 2;
    }
  }
  if (resolutions.empty())
  {
    resolutions = quick ? std::vector<int>{ 10 } : std::vector<int>{ 10, 20, 40 };
  }

  if (scene == "all" || scene == "hydrostatic")
  {
    std::ofstream hydro(dir + "/hydrostatic.csv");
    std::ofstream profile(dir + "/hydrostatic_profile.csv");
    hydro << "solver,particles_across,particles,steps,wall_s,relative_l2_error,profile_relative_l2_error,mean_"
             "compression\n";
    profile << "solver,particles_across,z,pressure,reference\n";
    for (PressureSolverType solver : solvers)
    {
      for (int across : resolutions)
      {
        const Hydrostatic r = hydrostatic(solver, across, &profile);
        hydro << name(solver) << "," << across << "," << r.particles << "," << r.steps << "," << r.wall << ","
              << r.error << "," << r.profileError << "," << r.compression << "\n";
        std::printf("hydrostatic %s %3d across: %6lld particles %6lld steps %8.2f s  L2 error per particle %.4f, "
                    "of the layer profile %.4f  compression %.5f\n",
                    name(solver), across, r.particles, r.steps, r.wall, r.error, r.profileError, r.compression);
        std::fflush(stdout);
      }
    }
  }
  if (scene == "all" || scene == "dambreak")
  {
    std::ofstream curve(dir + "/dambreak_front.csv");
    std::ofstream summary(dir + "/dambreak.csv");
    curve << "solver,particles_across,T,Z\n";
    summary << "solver,particles_across,particles,steps,wall_s,mean_relative_error,max_relative_error,"
               "mean_compression,max_compression,density_iterations,divergence_iterations\n";
    for (PressureSolverType solver : solvers)
    {
      for (int across : resolutions)
      {
        const DamBreak r = damBreak(solver, across, 3.0, curve);
        summary << name(solver) << "," << across << "," << r.particles << "," << r.steps << "," << r.wall << ","
                << r.meanError << "," << r.maxError << "," << r.meanCompression << "," << r.maxCompression << ","
                << r.densityIterations << "," << r.divergenceIterations << "\n";
        std::printf("dam break   %s %3d across: %6lld particles %6lld steps %8.2f s  front error mean %.3f max %.3f  "
                    "compression mean %.5f max %.5f  iterations %.1f + %.1f\n",
                    name(solver), across, r.particles, r.steps, r.wall, r.meanError, r.maxError, r.meanCompression,
                    r.maxCompression, r.densityIterations, r.divergenceIterations);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
