#pragma once
// The numerical kernels of the stable-fluids step on a StaggeredGrid (no state of their own):
// semi-Lagrangian advection (Stam 1999) with the optional MacCormack correction (Selle et al.
// 2008) and a conservative variant for the scalars, the discrete divergence, the boundary
// velocities (closed walls or open faces), the pressure projection by conjugate gradients
// preconditioned with a multigrid V-cycle (MGPCG, McAdams et al. 2010) or Jacobi, and implicit
// diffusion. Positions in metres, velocities in m/s, times in s.
#include "parafluid/clouds/StaggeredGrid.h"

#include <memory>
#include <vector>

namespace parafluid::clouds
{
/// `field` carried by the grid's velocity over dt [s] (may be negative): each sample traced back
/// along the flow and read there (trilinear, clamped at the box). MacCormack: a forward and a
/// backward trace, half the round trip's error added back, clamped to the samples the backward
/// trace blended (so it cannot overshoot); keeps sharp features sharp where plain tracing smears
/// them. Not conservative: see advectScalars.
GridArray advect(const GridArray& field, const StaggeredGrid& grid, double dt, bool macCormack);

/// The work arrays of the advection, kept between calls (a solver that advects every step
/// passes the same one; nullptr: made for the call).
struct AdvectionWorkspace;
std::shared_ptr<AdvectionWorkspace> makeAdvectionWorkspace();

/// The three velocity components carried by the (old) velocity.
void advectVelocity(StaggeredGrid& grid, double dt, bool macCormack, AdvectionWorkspace* workspace = nullptr);

struct ScalarField
{
  GridArray* field;     // cell-centred
  double ambient = 0.0; // the value outside open faces, and the level conservation is about
};
/// Cell-centred scalars carried by the grid's velocity, sharing one trace. `conservative`: the
/// total of (value - ambient) is kept exactly with closed walls (each source cell's content
/// shared out among the cells whose traces draw from it, after Lentine et al. 2011); with
/// `sharpen` the conservative step is wrapped in BFECC (Kim et al. 2005: the round trip's error
/// taken out first), clamped to what the trace blended, and blended back to the conserved total
/// cell by cell (a mass fixer after Priestley 1993: each cell stays between its low- and
/// high-order values). Not conservative: each field by advect(), MacCormack with `sharpen`.
void advectScalars(const StaggeredGrid& grid, const std::vector<ScalarField>& fields, double dt, bool sharpen,
                   bool conservative, AdvectionWorkspace* workspace = nullptr);

/// Outflow minus inflow of each cell's faces divided by h [1/s].
std::vector<double> divergence(const StaggeredGrid& grid);
/// The box faces' normal velocities: zero on closed faces, continued from inside on open ones.
void setBoundaryVelocities(StaggeredGrid& grid);

struct SolveReport
{
  int iterations = 0;
  // The final residual's 2-norm relative to the right-hand side's, or (the projection) to the
  // right-hand side a velocity field of the same RMS would make, whichever is larger.
  double residual = 0.0;
};
enum class Preconditioner
{
  Multigrid, // one symmetric V-cycle per iteration (MGPCG)
  Jacobi     // the diagonal: cheap iterations, many more of them
};
/// What a projection keeps between calls on one grid size (the multigrid hierarchy and its
/// work arrays): a solver that projects every step passes the same one.
struct ProjectionWorkspace;
std::shared_ptr<ProjectionWorkspace> makeProjectionWorkspace();

struct ProjectionOptions
{
  double tolerance = 1e-10; // relative residual
  int maxIterations = 2000;
  Preconditioner preconditioner = Preconditioner::Multigrid;
  bool warmStart = false;                   // start from the grid's last pressure
  ProjectionWorkspace* workspace = nullptr; // kept between calls; nullptr: made for this one
};
/// Makes the velocity divergence-free: solves the pressure's Poisson equation (7-point Laplacian,
/// zero normal derivative at closed walls, zero pressure beyond open faces) and subtracts the
/// pressure gradient from the face velocities; the pressure is left in grid.pressure.
SolveReport project(StaggeredGrid& grid, double dt, const ProjectionOptions& options);
SolveReport project(StaggeredGrid& grid, double dt, double tolerance = 1e-10, int maxIterations = 2000);

/// Implicit diffusion of `field` (samples of its own dims, Neumann ends): solves
/// (I - coefficient * dt / h^2 * Laplacian) x = field by CG. coefficient [m^2/s].
SolveReport diffuse(GridArray& field, double h, double coefficient, double dt, double tolerance = 1e-8,
                    int maxIterations = 500);
} // namespace parafluid::clouds
