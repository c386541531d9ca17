#pragma once
// The numerical kernels of the stable-fluids step on a StaggeredGrid (no state of their own):
// trilinear sampling, semi-Lagrangian advection (Stam 1999) with the optional MacCormack
// correction (Selle et al. 2008), the discrete divergence, and the pressure projection solved
// matrix-free by conjugate gradients with a Jacobi preconditioner. All boundaries are closed
// walls: the normal velocity on the box's faces is zero, the pressure's normal derivative too.
#include "parafluid/clouds/StaggeredGrid.h"

namespace parafluid::clouds
{
/// Trilinear value of `a` at the point p [m] (clamped into the array's samples); when `lo`/`hi`
/// are given, also the smallest and largest of the 8 samples it blends.
double sampleTrilinear(const GridArray& a, const StaggeredGrid& grid, const double p[3], double* lo = nullptr,
                       double* hi = nullptr);
/// The velocity [m/s] at p [m].
void sampleVelocity(const StaggeredGrid& grid, const double p[3], double velocity[3]);

/// `field` carried by the grid's velocity over dt [s] (may be negative): each sample traced back
/// along the flow (midpoint rule) and read there. MacCormack: a forward and a backward trace,
/// half the round trip's error added back, clamped to the samples the forward trace blended
/// (so it cannot overshoot); keeps sharp features sharp where plain tracing smears them.
GridArray advect(const GridArray& field, const StaggeredGrid& grid, double dt, bool macCormack);

/// Outflow minus inflow of each cell's faces divided by h [1/s].
std::vector<double> divergence(const StaggeredGrid& grid);
/// The zero-normal-velocity walls: the box faces' normal components set to 0.
void closeWalls(StaggeredGrid& grid);

struct SolveReport
{
  int iterations = 0;
  double residual = 0.0; // final residual's 2-norm relative to the right-hand side's
};
/// Makes the velocity divergence-free: solves the pressure's Poisson equation (7-point Laplacian
/// with Neumann walls) to a relative residual `tolerance` in at most `maxIterations` PCG
/// iterations, and subtracts the pressure gradient from the face velocities.
SolveReport project(StaggeredGrid& grid, double dt, double tolerance = 1e-10, int maxIterations = 2000);

/// Implicit diffusion of `field` (samples of its own dims, Neumann ends): solves
/// (I - coefficient * dt / h^2 * Laplacian) x = field by CG. coefficient [m^2/s].
SolveReport diffuse(GridArray& field, double h, double coefficient, double dt, double tolerance = 1e-8,
                    int maxIterations = 500);
} // namespace parafluid::clouds
