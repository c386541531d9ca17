#pragma once
// The pressure solvers SPH knows, one entry each: everything the rest of the code asks about a
// solver (its names, creator, kernel, default support, which time-step limits and options apply,
// what to change when it blows up). Each entry is written beside its solver (the solver's
// registryEntry()); nothing outside a solver's files and this registry switches on the solver type.
#include "parafluid/common/Kernels.h"
#include "parafluid/sph/SPHParameters.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace parafluid::sph
{
class PressureSolver;

/// The viscous operator whose lattice error the solver's laminar term is corrected for
/// (SPHParameters.h: latticeLaplacianCorrection and latticeMorrisLaplacianCorrection).
enum class ViscousOperator
{
  Monaghan,      // Monaghan (2005) with the density kernel's gradient
  MonaghanSpiky, // the same with the gradient of Müller's spiky kernel and poly6 volumes
  Morris         // Morris et al. (1997)
};

struct SolverEntry
{
  PressureSolverType type;
  const char* key;   // a plain name for command lines and CSV files ("DeltaSPH")
  const char* label; // the GUI label, as in the PressureSolver enumeration of the plugin XML
  int propertyValue; // the PressureSolver property's value (stored in saved states: never renumber)
  DensityKernel kernel;
  float defaultSupport; // h [particle spacings] when the input gives none
  float minimumSupport; // a narrower h from the input is widened to this [spacings] (0: kept)
  float maximumSupport; // the widest h the solver accepts [spacings] (0: no limit)
  ViscousOperator viscousOperator;
  bool explicitLaminarViscosity; // the laminar term is explicit, so it limits the step
  bool separateExtraViscosity;   // Müller's Viscosity is a term of its own (else folded into the laminar one)
  bool meshWallInSums;           // a boundary mesh adds its wall to the density and pressure sums
  bool meshWallInRunoff;         // ... also under the Rain filter's cloudburst
  bool colourFieldSurfaceTension;
  bool particleShifting;
  bool implicitViscosity;
  // Akinci's forces stronger than gravity at the particle scale are validated with this solver
  // (a resting drop holds); SPH Step warns where they are not.
  bool holdsStrongCohesion;
  float runoffCFLNumber; // the Rain filter's automatic CFL number for this solver
  // Every pass that reads neighbours' values refreshes the ghosts they read (DistributedSimulation).
  bool runsDistributed;
  std::unique_ptr<PressureSolver> (*create)();
  /// What to change when a run blows up, in SPH Step's property names.
  std::string (*stabilityAdvice)(bool adaptiveTimeStep);
};

/// Every solver, in the order of their property values.
const std::vector<SolverEntry>& solverRegistry();
/// The entry of `type` (throws std::invalid_argument for a value no entry has).
const SolverEntry& solverEntry(PressureSolverType type);
/// The entry whose key or label is `name`, or null.
const SolverEntry* findSolver(std::string_view name);
/// The entry whose property value is `value`, or null.
const SolverEntry* solverForPropertyValue(int value);
/// The support radius h [m] a solver runs with for particles of the given spacing [m]: the input's
/// own smoothing length when it has one (> 0), else the solver's default, widened to its minimum.
float defaultSmoothingLength(const SolverEntry& solver, double spacing, double inputSmoothingLength);
/// The lattice correction of p's solver's viscous operator (its ViscousOperator) at this particle
/// spacing [m], which every backend scales the laminar term and its time-step limit by.
float latticeViscousCorrection(const SPHParameters& p, float spacing);
} // namespace parafluid::sph
