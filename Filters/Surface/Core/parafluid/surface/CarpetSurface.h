#pragma once
// The carpet: a height-field surface for shallow flows over terrain.
//
// An n x n grid of cells over the domain in x, y holds, per cell, the height of the highest
// particle projecting into it. Where particles leave a cell the carpet does not vanish: it falls
// with `fallAcceleration` (per-cell vertical velocity) until particles arrive again or it sinks
// to within `minDepth` of the terrain, which leaves the trail a thin film leaves on a slope.
// Cells with no fluid above the terrain never enter the quadtree (it is built bottom-up from the
// sorted list of wet cells), so building it and emitting triangles cost O(wet cells), not O(n^2).
#include "parafluid/surface/SurfaceMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid::surface
{
class CarpetSurface
{
public:
  /// The grid: resolution x resolution cells over [x0, x1] x [y0, y1] [m]; terrain holds the
  /// ground height [m] at each cell centre (x fastest; resolution^2 values). Clears the state.
  /// Throws std::invalid_argument for a resolution outside [1, 65536], an empty domain or a
  /// terrain of the wrong size or with NaN heights.
  void setGrid(double x0, double y0, double x1, double y1, int resolution, std::vector<float> terrain);

  /// Forgets the carpet (the next advance starts from the particles alone).
  void reset();

  /// Moves the carpet on by dt [s] (dt = 0 for the first frame): cells with particles take the
  /// highest particle's z and stop falling; the others fall (h -= v dt + a dt^2 / 2, v += a dt)
  /// and are dropped once within minDepth [m] of the terrain. Particles outside the grid are
  /// ignored; NaN positions throw std::invalid_argument.
  void advance(const float* xyz, std::size_t n, double dt, double fallAcceleration, double minDepth);

  /// The carpet as triangles (two per wet cell, corners shared; a corner's height is the mean of
  /// the wet cells around it) with outward (upward) normals, and per vertex the fluid depth above
  /// the terrain [m]. visitedNodes (optional) counts the quadtree nodes the traversal entered.
  SurfaceMesh mesh(std::vector<float>* depth = nullptr, std::size_t* visitedNodes = nullptr) const;

  std::size_t wetCells() const { return this->Cells.size(); }
  std::size_t quadtreeNodes() const;
  int resolution() const { return this->N; }
  /// Mean carpet height over the wet cells below quadtree node (level, i, j) (level 0 = cells,
  /// each level up halves the resolution); NaN where that subtree holds no fluid.
  double meanHeight(int level, int i, int j) const;
  /// Carpet height of cell (i, j); NaN when dry.
  double cellHeight(int i, int j) const { return this->meanHeight(0, i, j); }

private:
  struct Cell
  {
    std::uint32_t code; // Morton code of (i, j)
    float height;       // carpet height [m]
    float velocity;     // downward speed [m/s]; 0 while particles hold it up
  };
  struct Node
  {
    std::uint32_t code;       // Morton code at this level
    std::uint32_t firstChild; // index into the level below
    std::uint32_t childCount;
    float minTerrain, maxFluid, meanHeight;
  };
  void buildQuadtree();
  float terrainAt(std::uint32_t code) const;

  double X0 = 0, Y0 = 0, DX = 1, DY = 1;
  int N = 0;
  std::vector<float> Terrain;
  std::vector<Cell> Cells;               // wet cells sorted by code
  std::vector<std::vector<Node>> Levels; // Levels[0]: one node per wet cell; last: the root
};

/// Morton (Z-order) code of cell (i, j), i and j < 2^16, and its inverse.
std::uint32_t mortonCode(std::uint32_t i, std::uint32_t j);
void mortonDecode(std::uint32_t code, std::uint32_t& i, std::uint32_t& j);
} // namespace parafluid::surface
