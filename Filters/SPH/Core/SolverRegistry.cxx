#include "parafluid/sph/SolverRegistry.h"

#include "parafluid/sph/DFSPHSolver.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/WCSPHSolver.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace parafluid::sph
{
const std::vector<SolverEntry>& solverRegistry()
{
  static const std::vector<SolverEntry> entries = []
  {
    std::vector<SolverEntry> all = { WCSPHSolver::registryEntry(), DFSPHSolver::registryEntry(),
                                     DeltaSPHSolver::registryEntry() };
    std::sort(all.begin(), all.end(),
              [](const SolverEntry& a, const SolverEntry& b) { return a.propertyValue < b.propertyValue; });
    return all;
  }();
  return entries;
}

const SolverEntry& solverEntry(PressureSolverType type)
{
  for (const SolverEntry& entry : solverRegistry())
  {
    if (entry.type == type)
    {
      return entry;
    }
  }
  throw std::invalid_argument("SPH: unknown pressure solver " + std::to_string(static_cast<int>(type)));
}

const SolverEntry* findSolver(std::string_view name)
{
  for (const SolverEntry& entry : solverRegistry())
  {
    if (name == entry.key || name == entry.label)
    {
      return &entry;
    }
  }
  return nullptr;
}

const SolverEntry* solverForPropertyValue(int value)
{
  for (const SolverEntry& entry : solverRegistry())
  {
    if (entry.propertyValue == value)
    {
      return &entry;
    }
  }
  return nullptr;
}

std::unique_ptr<PressureSolver> makePressureSolver(PressureSolverType type)
{
  return solverEntry(type).create();
}

float defaultSmoothingLength(const SolverEntry& solver, double spacing, double inputSmoothingLength)
{
  const double h = inputSmoothingLength > 0.0 ? inputSmoothingLength : solver.defaultSupport * spacing;
  return static_cast<float>(std::max(h, static_cast<double>(solver.minimumSupport) * spacing));
}

float latticeViscousCorrection(const SPHParameters& p, float spacing)
{
  switch (solverEntry(p.pressureSolver).viscousOperator)
  {
    case ViscousOperator::Morris:
      return latticeMorrisLaplacianCorrection(spacing, p.smoothingLength, p.densityKernel());
    case ViscousOperator::MonaghanSpiky:
      return latticeLaplacianCorrection(spacing, p.smoothingLength, DensityKernel::Poly6, true);
    case ViscousOperator::Monaghan:
      break;
  }
  return latticeLaplacianCorrection(spacing, p.smoothingLength, p.densityKernel(), false);
}
} // namespace parafluid::sph
