#pragma once
// The body forces of the stable-fluids step on the staggered grid, row by row: a value per cell
// moved onto the faces between cells, and the vorticity-confinement force per cell (Fedkiw, Stam &
// Jensen 2001). The rows run as plain loops that vectorise.
#include "parafluid/clouds/StaggeredGrid.h"

#include <vector>

namespace parafluid::clouds::detail
{
/// faces (the array of `axis`'s faces) += scale times the mean of perCell over the two cells either
/// side of each face; with `interiorOnly` the faces on the box's walls are left alone, else they
/// take their one cell's value.
void addCellValuesToFaces(const StaggeredGrid& g, GridArray& faces, int axis, const double* perCell, double scale,
                          bool interiorOnly);

/// The arrays the forces are worked out in, kept between steps.
struct ForceScratch
{
  std::vector<double> lift;                   // buoyancy per cell [m/s^2]
  std::vector<float> vorticity[3], magnitude; // omega and |omega| per cell [1/s]
};

/// The faces between cells += dt times the mean of the two cells' vorticity-confinement force
/// epsilon h (N x omega), omega the curl of the cell-centred velocity and N the unit gradient of
/// |omega| (central differences, one-sided at the walls; zero where that gradient vanishes). The
/// faces on the walls are left alone. Two passes over the grid: omega, then the force onto the
/// faces row by row, without a per-cell force array.
void addVorticityConfinement(StaggeredGrid& g, double epsilon, double dt, ForceScratch& scratch);
} // namespace parafluid::clouds::detail
