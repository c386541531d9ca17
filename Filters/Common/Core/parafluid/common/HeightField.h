#pragma once
// A height field: elevation on a regular grid in x, y (bilinear between nodes, held constant beyond
// the grid's edges) and a water level above it, giving the depth of water anywhere. The ocean's
// sea floor (ocean::Bathymetry) and the carpet surface's terrain are height fields.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid
{
class HeightField
{
public:
  /// elevation: nx * ny floor heights z [m], x fastest, at (x0 + i dx, y0 + j dy); seaLevel [m].
  /// Throws std::invalid_argument for fewer than 2 x 2 nodes, non-positive spacing, a size
  /// mismatch or a NaN elevation.
  HeightField(std::vector<float> elevation, int nx, int ny, double x0, double y0, double dx, double dy,
              double seaLevel);

  /// Rasterises a triangulated terrain surface (x, y, z per point; three indices per triangle)
  /// onto nx * ny nodes over its x-y bounds, keeping the highest surface over each node. Nodes
  /// no triangle covers take the lowest elevation of the mesh (the open sea beyond the terrain).
  static HeightField fromTriangles(const std::vector<float>& points, const std::vector<std::uint32_t>& triangles,
                                   int nx, int ny, double seaLevel);

  /// Elevation [m] at (x, y).
  double heightAt(double x, double y) const;
  /// Water depth [m] at (x, y): sea level minus the floor; zero or negative on land.
  double depth(double x, double y) const;
  /// Gradient of the depth [m/m] at (x, y) (of the bilinear interpolant, per cell).
  void depthGradient(double x, double y, double gradient[2]) const;

  int nodesX() const { return this->NX; }
  int nodesY() const { return this->NY; }
  double seaLevel() const { return this->SeaLevel; }
  /// x0, x1, y0, y1 of the grid [m].
  void bounds(double b[4]) const;
  double spacing() const { return this->DX < this->DY ? this->DX : this->DY; }
  /// The grid as stored: elevations (x fastest), origin and spacing (for GPU upload).
  const std::vector<float>& elevation() const { return this->Elevation; }
  void grid(double origin[2], double spacing[2]) const
  {
    origin[0] = this->X0, origin[1] = this->Y0, spacing[0] = this->DX, spacing[1] = this->DY;
  }

private:
  /// Cell (i, j) and the fractions (fx, fy) of (x, y) inside it, clamped to the grid.
  void locate(double x, double y, int& i, int& j, double& fx, double& fy) const;
  double elevationAt(int i, int j) const { return this->Elevation[static_cast<std::size_t>(j) * this->NX + i]; }

  std::vector<float> Elevation;
  int NX = 0, NY = 0;
  double X0 = 0.0, Y0 = 0.0, DX = 1.0, DY = 1.0, SeaLevel = 0.0;
};
} // namespace parafluid
