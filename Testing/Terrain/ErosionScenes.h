#pragma once
// Terrains with known shapes for the erosion tests.
#include "parafluid/terrain/ElevationGrid.h"
#include "parafluid/terrain/TerrainGenerator.h"

#include <cmath>

namespace parafluid::terrain::test
{
/// A V-shaped valley along y (floor at x = n/2, flanks rising 0.2 m per metre, the V's tip
/// rounded over a few metres as a hyperbola), its floor falling 0.4 m per metre (a mountain stream: steeper along than
/// across) towards y = foot, below which the ground is a flat plain: water runs into the floor line, down it, and slows
/// on the plain.
inline ElevationGrid valley(int n, int foot)
{
  ElevationGrid g;
  g.nx = g.ny = n;
  g.elevation.resize(g.size());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double side = 0.2 * (std::hypot(i - n / 2, 3.0) - 3.0);
      const double along = j > foot ? 0.4 * (j - foot) : 0.0;
      g.elevation[g.index(i, j)] = static_cast<float>(j > foot ? side + along : 0.0);
    }
  }
  return g;
}

inline ElevationGrid flat(int n, float height)
{
  ElevationGrid g;
  g.nx = g.ny = n;
  g.elevation.assign(g.size(), height);
  return g;
}

inline ElevationGrid hills(int n, double spacing)
{
  ElevationGrid g;
  g.nx = g.ny = n;
  g.dx = g.dy = spacing;
  TerrainSettings s;
  s.seed = 3;
  s.featureSize = n * spacing / 2;
  s.heightScale = n * spacing / 8;
  generateTerrain(s, g);
  return g;
}

/// Mean of `values` over the samples with i in [i0, i1) and j in [j0, j1).
inline double meanOver(const ElevationGrid& g, const std::vector<float>& values, int i0, int i1, int j0, int j1)
{
  double sum = 0.0;
  for (int j = j0; j < j1; ++j)
  {
    for (int i = i0; i < i1; ++i)
    {
      sum += values[g.index(i, j)];
    }
  }
  return sum / ((i1 - i0) * (j1 - j0));
}
} // namespace parafluid::terrain::test
