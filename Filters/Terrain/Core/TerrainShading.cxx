#include "parafluid/terrain/TerrainShading.h"

#include <cmath>

namespace parafluid::terrain
{
void terrainGradient(const ElevationGrid& g, int i, int j, double gradient[2])
{
  const int i0 = i > 0 ? i - 1 : i, i1 = i < g.nx - 1 ? i + 1 : i;
  const int j0 = j > 0 ? j - 1 : j, j1 = j < g.ny - 1 ? j + 1 : j;
  gradient[0] = (static_cast<double>(g.at(i1, j)) - g.at(i0, j)) / (g.dx * (i1 - i0));
  gradient[1] = (static_cast<double>(g.at(i, j1)) - g.at(i, j0)) / (g.dy * (j1 - j0));
}

std::vector<float> terrainSlope(const ElevationGrid& g)
{
  std::vector<float> slope(g.size());
  constexpr double kDegrees = 57.29577951308232;
#pragma omp parallel for schedule(static)
  for (int j = 0; j < g.ny; ++j)
  {
    for (int i = 0; i < g.nx; ++i)
    {
      double grad[2];
      terrainGradient(g, i, j, grad);
      slope[g.index(i, j)] = static_cast<float>(std::atan(std::hypot(grad[0], grad[1])) * kDegrees);
    }
  }
  return slope;
}

std::vector<float> terrainCurvature(const ElevationGrid& g)
{
  std::vector<float> curvature(g.size());
#pragma omp parallel for schedule(static)
  for (int j = 0; j < g.ny; ++j)
  {
    for (int i = 0; i < g.nx; ++i)
    {
      const double h = g.at(i, j);
      const double left = g.at(i > 0 ? i - 1 : i + 1, j), right = g.at(i < g.nx - 1 ? i + 1 : i - 1, j);
      const double down = g.at(i, j > 0 ? j - 1 : j + 1), up = g.at(i, j < g.ny - 1 ? j + 1 : j - 1);
      curvature[g.index(i, j)] =
        static_cast<float>((left + right - 2.0 * h) / (g.dx * g.dx) + (down + up - 2.0 * h) / (g.dy * g.dy));
    }
  }
  return curvature;
}

std::vector<float> terrainNormals(const ElevationGrid& g)
{
  std::vector<float> normals(3 * g.size());
#pragma omp parallel for schedule(static)
  for (int j = 0; j < g.ny; ++j)
  {
    for (int i = 0; i < g.nx; ++i)
    {
      double grad[2];
      terrainGradient(g, i, j, grad);
      const double length = std::sqrt(grad[0] * grad[0] + grad[1] * grad[1] + 1.0);
      float* n = normals.data() + 3 * g.index(i, j);
      n[0] = static_cast<float>(-grad[0] / length);
      n[1] = static_cast<float>(-grad[1] / length);
      n[2] = static_cast<float>(1.0 / length);
    }
  }
  return normals;
}
} // namespace parafluid::terrain
