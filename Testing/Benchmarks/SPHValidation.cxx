// Run time against error of the SPH solvers on flows with known answers (Testing/SPH/Validation):
//  - hydrostatic column and still water (rho0 g depth);
//  - dam break against Martin & Moyce (1952): surge front and residual column height;
//  - dam break against Lobovsky et al. (2014): the pressure on the downstream wall;
//  - Taylor-Green vortex (energy decay), Poiseuille flow (profile), standing wave (frequency);
//  - a weightless drop's oscillation under surface tension (Akinci's two terms) against Rayleigh.
// Writes <scene>.csv (one row per solver and resolution) and <scene>_curves.csv into the directory
// given as first argument; plot_validation.py draws them.
// Usage: ParaFluidSPHValidation <output-directory> [--scene all|hydrostatic|stillwater|dambreak|
//        lobovsky|taylorgreen|poiseuille|standingwave|drop|lattice] [--solver WCSPH|DFSPH|DeltaSPH]
//        [--resolutions 10,20,40] [--kernel-ratio r] (h / spacing of the chosen solvers)
//        [--no-push-high-pass] (δ-SPH's SPHParameters::pushHighPass off)
//        [--density-tolerance x] [--max-time-step s] (DFSPH's densityTolerance, any solver's
//        maxTimeStep [s]: probes of the solvers' limits, not the defaults the tables report)
#include "SPHScenes.h"

#include "parafluid/sph/SolverRegistry.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace parafluid;
using namespace parafluid::validation;
using sph::PressureSolverType;

namespace
{
const char* const kUsage =
  "usage: ParaFluidSPHValidation <output-directory> [--scene all|hydrostatic|stillwater|dambreak|lobovsky|\n"
  "         taylorgreen|poiseuille|standingwave|drop|lattice] [--solver WCSPH|DFSPH|DeltaSPH]\n"
  "         [--resolutions 10,20,40] [--kernel-ratio r] [--no-push-high-pass]\n"
  "         [--density-tolerance x] [--max-time-step s]\n";

/// One scene: its default resolutions, its CSV header, and a run that prints and returns a CSV row.
struct Scene
{
  std::vector<int> resolutions;
  std::string header;
  std::function<std::string(PressureSolverType, int, std::ostream&)> run;
};

std::string cost(const RunCost& c)
{
  return std::to_string(c.particles) + "," + std::to_string(c.steps) + "," + std::to_string(c.seconds);
}

std::map<std::string, Scene> scenes()
{
  std::map<std::string, Scene> all;
  all["hydrostatic"] = { { 10, 20, 40 },
                         "relative_l2_error,mean_compression,layer_mean_error,within_layer_error",
                         [](PressureSolverType s, int n, std::ostream& curves)
                         {
                           const Hydrostatic r = hydrostatic(s, n, &curves);
                           std::printf("hydrostatic  %-8s %3d: %7lld particles %7lld steps %8.1f s  L2 error %.4f "
                                       "(layers' means %.4f, scatter within layers %.4f)\n",
                                       solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.error,
                                       r.layerMeanError, r.withinLayerError);
                           return cost(r.cost) + "," + std::to_string(r.error) + "," + std::to_string(r.compression) +
                                  "," + std::to_string(r.layerMeanError) + "," + std::to_string(r.withinLayerError);
                         } };
  all["stillwater"] = { { 10, 20, 40 },
                        "largest_speed_over_sqrt_gH,pressure_l2_error,closest_to_wall_spacings,"
                        "largest_drift_spacings",
                        [](PressureSolverType s, int n, std::ostream&)
                        {
                          const StillWater r = stillWater(s, n, 10.0);
                          std::printf("still water  %-8s %3d: %7lld particles %7lld steps %8.1f s  speed %.2e sqrt(gH) "
                                      "pressure error %.4f closest to a wall %.2f d drift %.3f d\n",
                                      solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.largestSpeed,
                                      r.pressureError, r.closestToWall, r.highestDrift);
                          return cost(r.cost) + "," + std::to_string(r.largestSpeed) + "," +
                                 std::to_string(r.pressureError) + "," + std::to_string(r.closestToWall) + "," +
                                 std::to_string(r.highestDrift);
                        } };
  all["dambreak"] = { { 10, 20, 40 },
                      "front_mean_error,front_max_error,height_mean_error,height_max_error,"
                      "mean_compression",
                      [](PressureSolverType s, int n, std::ostream& curves)
                      {
                        const DamBreak r = martinMoyce(s, n, &curves);
                        std::printf("dam break    %-8s %3d: %7lld particles %7lld steps %8.1f s  front error mean %.3f "
                                    "max %.3f  height error mean %.3f max %.3f\n",
                                    solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.frontMeanError,
                                    r.frontMaxError, r.heightMeanError, r.heightMaxError);
                        return cost(r.cost) + "," + std::to_string(r.frontMeanError) + "," +
                               std::to_string(r.frontMaxError) + "," + std::to_string(r.heightMeanError) + "," +
                               std::to_string(r.heightMaxError) + "," + std::to_string(r.meanCompression);
                      } };
  all["lobovsky"] = { { 20, 40, 80 },
                      "peak_time,peak_pressure,peak_time_error,peak_pressure_error,arrival_error",
                      [](PressureSolverType s, int n, std::ostream& curves)
                      {
                        const Lobovsky r = lobovsky(s, n, &curves);
                        std::printf("Lobovsky     %-8s %3d: %7lld particles %7lld steps %8.1f s  first peak %.3f at t* "
                                    "%.3f (errors %.3f, %.3f) arrival error %.3f\n",
                                    solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.peakPressure,
                                    r.peakTime, r.peakPressureError, r.peakTimeError, r.frontError);
                        return cost(r.cost) + "," + std::to_string(r.peakTime) + "," + std::to_string(r.peakPressure) +
                               "," + std::to_string(r.peakTimeError) + "," + std::to_string(r.peakPressureError) + "," +
                               std::to_string(r.frontError);
                      } };
  all["lattice"] = { { 10, 12, 16 },
                     "rms_speed,largest_speed,mean_pressure",
                     [](PressureSolverType s, int n, std::ostream& curves)
                     {
                       const PressurisedLattice r = pressurisedLattice(s, n, &curves);
                       std::printf("lattice      %-8s %3d: %7lld particles %7lld steps %8.1f s  rms speed %.2e m/s "
                                   "largest %.2e m/s (mean pressure %.0f Pa)\n",
                                   solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.rmsSpeed,
                                   r.largestSpeed, r.meanPressure);
                       return cost(r.cost) + "," + std::to_string(r.rmsSpeed) + "," + std::to_string(r.largestSpeed) +
                              "," + std::to_string(r.meanPressure);
                     } };
  all["taylorgreen"] = { { 25, 50, 100 },
                         "energy_decay_error",
                         [](PressureSolverType s, int n, std::ostream& curves)
                         {
                           const TaylorGreen r = taylorGreen(s, n, &curves);
                           std::printf("Taylor-Green %-8s %3d: %7lld particles %7lld steps %8.1f s  decay error %.4f\n",
                                       solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.decayError);
                           return cost(r.cost) + "," + std::to_string(r.decayError);
                         } };
  all["poiseuille"] = { { 10, 20, 40 },
                        "profile_error,viscosity_iterations",
                        [](PressureSolverType s, int n, std::ostream& curves)
                        {
                          const Poiseuille r = poiseuille(s, n, &curves);
                          std::printf("Poiseuille   %-8s %3d: %7lld particles %7lld steps %8.1f s  profile error %.4f "
                                      "(CG iterations %d)\n",
                                      solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.profileError,
                                      r.viscosityIterations);
                          return cost(r.cost) + "," + std::to_string(r.profileError) + "," +
                                 std::to_string(r.viscosityIterations);
                        } };
  all["standingwave"] = { { 10, 20, 40 },
                          "frequency,exact,frequency_error",
                          [](PressureSolverType s, int n, std::ostream& curves)
                          {
                            const StandingWave r = standingWave(s, n, &curves);
                            std::printf("standing wave %-8s %3d: %7lld particles %7lld steps %8.1f s  omega %.4f "
                                        "(exact %.4f) error %.4f\n",
                                        solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.frequency,
                                        r.exact, r.frequencyError);
                            return cost(r.cost) + "," + std::to_string(r.frequency) + "," + std::to_string(r.exact) +
                                   "," + std::to_string(r.frequencyError);
                          } };
  all["drop"] = { { 8, 10, 14 },
                  "period,rayleigh,period_error,sigma_ratio,largest_density,crossings",
                  [](PressureSolverType s, int n, std::ostream& curves)
                  {
                    const Drop r = oscillatingDrop(s, n, &curves);
                    std::printf("drop         %-8s %3d: %7lld particles %7lld steps %8.1f s  period %.2f ms (Rayleigh "
                                "%.2f ms) error %.4f sigma ratio %.3f\n",
                                solverName(s), n, r.cost.particles, r.cost.steps, r.cost.seconds, r.period * 1e3,
                                r.rayleigh * 1e3, r.periodError, r.sigmaRatio);
                    return cost(r.cost) + "," + std::to_string(r.period) + "," + std::to_string(r.rayleigh) + "," +
                           std::to_string(r.periodError) + "," + std::to_string(r.sigmaRatio) + "," +
                           std::to_string(r.largestDensity) + "," + std::to_string(r.crossings);
                  } };
  return all;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << kUsage;
    return 2;
  }
  const std::string dir = argv[1];
  std::string chosen = "all";
  std::vector<PressureSolverType> solvers;
  for (const sph::SolverEntry& entry : sph::solverRegistry())
  {
    solvers.push_back(entry.type);
  }
  std::vector<int> resolutions;
  float ratio = 0.0f, densityTolerance = 0.0f, maxTimeStep = 0.0f;
  for (int k = 2; k < argc; ++k)
  {
    const std::string option = argv[k];
    if (option == "--kernel-ratio" && k + 1 < argc)
    {
      ratio = std::stof(argv[++k]);
    }
    else if ((option == "--density-tolerance" || option == "--max-time-step") && k + 1 < argc)
    {
      const float value = std::strtof(argv[++k], nullptr);
      if (!(value > 0.0f) || !std::isfinite(value))
      {
        std::cerr << option << " takes a positive finite number\n";
        return 2;
      }
      (option == "--density-tolerance" ? densityTolerance : maxTimeStep) = value;
    }
    else if (option == "--no-push-high-pass")
    {
      setPushHighPass(false);
    }
    else if (option == "--scene" && k + 1 < argc)
    {
      chosen = argv[++k];
    }
    else if (option == "--solver" && k + 1 < argc)
    {
      const sph::SolverEntry* entry = sph::findSolver(argv[++k]);
      if (!entry)
      {
        std::cerr << "--solver takes one of:";
        for (const sph::SolverEntry& e : sph::solverRegistry())
        {
          std::cerr << " " << e.key;
        }
        std::cerr << "\n";
        return 2;
      }
      solvers = { entry->type };
    }
    else if (option == "--resolutions" && k + 1 < argc)
    {
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
  setSolveLimits(densityTolerance, maxTimeStep);
  if (ratio > 0.0f)
  {
    for (PressureSolverType solver : solvers)
    {
      setKernelRatio(solver, ratio);
    }
  }
  const auto all = scenes();
  if (chosen != "all" && all.count(chosen) == 0)
  {
    std::cerr << "unknown scene " << chosen << "\n" << kUsage;
    return 2;
  }
  for (const auto& [name, scene] : all)
  {
    if (chosen != "all" && chosen != name)
    {
      continue;
    }
    std::ofstream summary(dir + "/" + name + ".csv");
    std::ofstream curves(dir + "/" + name + "_curves.csv");
    summary << "solver,particles_across,particles,steps,wall_s," << scene.header << "\n";
    // Coarse to fine, every solver at each resolution before the next: a run cut short by a time
    // limit still compares the solvers.
    for (int across : resolutions.empty() ? scene.resolutions : resolutions)
    {
      for (PressureSolverType solver : solvers)
      {
        try
        {
          const std::string row = scene.run(solver, across, curves);
          summary << solverName(solver) << "," << across << "," << row << std::endl;
        }
        catch (const std::exception& e)
        {
          // A run that blows up is a result too: recorded, and the others go on.
          std::printf("%-12s %-8s %3d: stopped: %s\n", name.c_str(), solverName(solver), across, e.what());
          summary << solverName(solver) << "," << across << ",stopped" << std::endl;
        }
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
