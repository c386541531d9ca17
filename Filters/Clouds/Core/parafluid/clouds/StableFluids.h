#pragma once
// Stam's stable fluids (SIGGRAPH 1999) for clouds and smoke on a StaggeredGrid, one step:
//  1. sources: inside the emitter box, density and temperature raised to the emitter's values
//     and the vertical velocity to its speed;
//  2. forces: buoyancy w += dt (-alpha density + beta (T - ambient)) (Fedkiw, Stam & Jensen
//     2001), and vorticity confinement f = epsilon h (N x omega), N the unit gradient of |omega|
//     (same paper), which puts back the small swirls the grid's numerical diffusion takes out;
//  3. advection of velocity, density and temperature (semi-Lagrangian; `macCormack` sharpens it:
//     MacCormack for the velocity, BFECC around the conservative step for the scalars);
//  4. implicit diffusion (viscosity of the velocity, diffusivity of the scalars);
//  5. projection to zero divergence (MGPCG from the last step's pressure).
// Unconditionally stable in dt: the tracing reads values that exist, the solves are implicit.
#include "parafluid/clouds/GridSolvers.h"
#include "parafluid/clouds/StaggeredGrid.h"

#include <memory>

namespace parafluid::clouds
{
namespace detail
{
struct ForceScratch;
}

/// Where the last step's time went [ms] (steady clock).
struct StepTimings
{
  double forces = 0.0;          // sources, buoyancy, vorticity confinement
  double advection = 0.0;       // of everything
  double scalarAdvection = 0.0; // of density and temperature (part of `advection`)
  double diffusion = 0.0;
  double projection = 0.0;
};

struct StableFluidsParameters
{
  int resolution[3] = { 32, 32, 32 }; // cells per axis
  double cellSize = 0.1;              // [m]
  double origin[3] = { 0.0, 0.0, 0.0 };
  bool macCormack = true;
  bool conservative = true; // density and temperature: conserved exactly with closed walls
  bool open[6] = { false, false, false, false, false, false }; // xmin, xmax, ymin, ymax, zmin, zmax
  double viscosity = 0.0;                                      // kinematic [m^2/s]; 0: no diffusion solve
  double diffusivity = 0.0;                                    // of density and temperature [m^2/s]
  double buoyancyDensity = 0.05;   // alpha [m/s^2 per unit density]: density weighs the air down
  double buoyancyHeat = 0.2;       // beta [m/s^2 per K]: heat lifts it
  double ambientTemperature = 0.0; // [K] (relative)
  double vorticity = 0.0;          // epsilon [1]
  double gravityDirection[3] = { 0.0, 0.0, -1.0 };
  bool emitter = false;
  double emitterBox[6] = { 0, 0, 0, 0, 0, 0 }; // xmin, xmax, ymin, ymax, zmin, zmax [m]
  double emitterDensity = 1.0;
  double emitterTemperature = 10.0; // [K] above ambient
  double emitterSpeed = 0.0;        // [m/s] along minus gravity
  // The pressure solve's relative residual: the divergence left is this fraction of the
  // divergence the step's forces and advection made.
  double projectionTolerance = 1e-5;
  int projectionIterations = 1000;
  Preconditioner preconditioner = Preconditioner::Multigrid;
};

class StableFluids
{
public:
  /// Throws std::invalid_argument for a resolution below 2 or above 1024 per axis (or more
  /// than 2^27 cells), a non-positive or non-finite cell size, dt, or negative coefficients.
  explicit StableFluids(const StableFluidsParameters& parameters);
  void step(double dt);
  /// Points [m] (x, y, z, ...) that inject like the emitter box, into the cell holding each one,
  /// every step (e.g. particles, or a terrain's valleys); cleared by an empty list.
  void setPointSources(std::vector<double> xyz) { this->PointSources = std::move(xyz); }
  const StaggeredGrid& grid() const { return this->Grid; }
  StaggeredGrid& grid() { return this->Grid; }
  const SolveReport& lastProjection() const { return this->Projection; }
  const StepTimings& lastTimings() const { return this->Timings; }
  /// Sum of density over the cells times a cell's volume.
  double totalDensity() const;
  /// 1/2 sum of the squared face velocities times a cell's volume (each face's share).
  double kineticEnergy() const;
  /// The fastest face velocity component now, or the emitter's (and point sources') speed if
  /// faster: what the next step's sources set [m/s].
  double fastestSpeed() const;
  /// The longest step [s] in which the fastest flow crosses kMaxCellsPerStep cells (infinite in
  /// still air): longer traces smear the flow, and past open faces the conservative advection's
  /// work grows with the cube of the cells a trace crosses.
  double longestStableStep() const;
  static constexpr double kMaxCellsPerStep =
    5.0; // the CFL number semi-Lagrangian solvers run at (Stam 1999; Fedkiw et al. 2001)

private:
  void applySources(double dt);
  void applyForces(double dt);
  StableFluidsParameters P;
  StaggeredGrid Grid;
  SolveReport Projection;
  std::shared_ptr<ProjectionWorkspace> Workspace = makeProjectionWorkspace();
  std::shared_ptr<AdvectionWorkspace> Advection = makeAdvectionWorkspace();
  StepTimings Timings;
  std::shared_ptr<detail::ForceScratch> Forces; // the forces' work arrays, kept between steps
  std::vector<double> PointSources;
};
} // namespace parafluid::clouds
