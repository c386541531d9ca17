#pragma once
// A box of nx x ny x nz cubic cells of side h [m] from `origin`, with the velocity on the cells'
// faces (a staggered "MAC" grid: u on the x faces, v on the y faces, w on the z faces) and scalars
// at the cells' centres. On this grid the discrete divergence of a cell and the pressure gradient
// across a face are each one difference, so a projection can drive the divergence to the
// solver's tolerance (a collocated grid leaves a checkerboard that it cannot see).
#include <array>
#include <cstddef>
#include <vector>

namespace parafluid::clouds
{
/// One array on the grid: `dims` samples per axis, x fastest, sample (i, j, k) at
/// origin + h * (i + offset[0], j + offset[1], k + offset[2]).
struct GridArray
{
  std::array<int, 3> dims{ 0, 0, 0 };
  std::array<double, 3> offset{ 0.5, 0.5, 0.5 };
  std::vector<double> values;

  void resize(int nx, int ny, int nz, std::array<double, 3> at)
  {
    dims = { nx, ny, nz };
    offset = at;
    values.assign(static_cast<std::size_t>(nx) * ny * nz, 0.0);
  }
  std::size_t index(int i, int j, int k) const { return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i; }
  double& at(int i, int j, int k) { return values[index(i, j, k)]; }
  double at(int i, int j, int k) const { return values[index(i, j, k)]; }
};

struct StaggeredGrid
{
  int nx = 0, ny = 0, nz = 0;
  double h = 1.0;
  std::array<double, 3> origin{ 0.0, 0.0, 0.0 };
  GridArray u, v, w;              // [m/s] on the x, y and z faces
  GridArray density, temperature; // [1], [K] at the centres
  GridArray pressure;             // [m^2/s^2] (pressure over density) at the centres, the last projection's
  /// Which box faces are open (xmin, xmax, ymin, ymax, zmin, zmax): air flows through them freely
  /// (zero pressure outside, ambient scalars flow in); the others are closed walls.
  std::array<bool, 6> open{ false, false, false, false, false, false };

  void resize(int x, int y, int z, double cell)
  {
    nx = x;
    ny = y;
    nz = z;
    h = cell;
    u.resize(x + 1, y, z, { 0.0, 0.5, 0.5 });
    v.resize(x, y + 1, z, { 0.5, 0.0, 0.5 });
    w.resize(x, y, z + 1, { 0.5, 0.5, 0.0 });
    density.resize(x, y, z, { 0.5, 0.5, 0.5 });
    temperature.resize(x, y, z, { 0.5, 0.5, 0.5 });
    pressure.resize(x, y, z, { 0.5, 0.5, 0.5 });
  }
  bool anyOpen() const { return open[0] || open[1] || open[2] || open[3] || open[4] || open[5]; }
  std::size_t cells() const { return static_cast<std::size_t>(nx) * ny * nz; }
};
} // namespace parafluid::clouds
