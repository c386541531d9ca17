#pragma once
// The terrain contract in the core: elevation [m] on a regular x-y grid (x fastest), with its
// origin and spacing [m]. Every terrain source and filter reads and writes this.
#include <cstddef>
#include <string>
#include <vector>

namespace parafluid::terrain
{
struct ElevationGrid
{
  int nx = 0, ny = 0;
  double x0 = 0.0, y0 = 0.0; // [m]
  double dx = 1.0, dy = 1.0; // [m]
  std::vector<float> elevation;

  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + i; }
  float at(int i, int j) const { return elevation[index(i, j)]; }
  /// Empty when usable; else one sentence naming what is wrong (size, spacing, NaN).
  std::string problem() const;
};

/// Replaces the values where `valid` is 0 (no-data) by the mean of their valid neighbours,
/// growing inwards from the edges of each hole one ring per sweep (a hole's filling is a smooth
/// continuation of its rim). Returns the number of values filled. Throws std::invalid_argument
/// when no value at all is valid or the sizes disagree.
std::size_t fillNoData(std::vector<float>& values, int nx, int ny, std::vector<unsigned char> valid);
} // namespace parafluid::terrain
