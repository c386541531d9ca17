#include "parafluid/rain/GroundSurface.h"

#include <algorithm>
#include <cmath>

namespace parafluid::rain
{
std::shared_ptr<const TriangleBoundary> groundBoundary(const HeightField& ground)
{
  const int nx = ground.nodesX(), ny = ground.nodesY();
  double origin[2], spacing[2];
  ground.grid(origin, spacing);
  const auto& z = ground.elevation();
  std::vector<float> points(3 * static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      points[3 * k] = static_cast<float>(origin[0] + i * spacing[0]);
      points[3 * k + 1] = static_cast<float>(origin[1] + j * spacing[1]);
      points[3 * k + 2] = z[k];
    }
  }
  std::vector<std::uint32_t> triangles;
  triangles.reserve(6 * static_cast<std::size_t>(nx - 1) * (ny - 1));
  for (int j = 0; j + 1 < ny; ++j)
  {
    for (int i = 0; i + 1 < nx; ++i)
    {
      const auto a = static_cast<std::uint32_t>(j * nx + i), b = a + 1, c = a + static_cast<std::uint32_t>(nx) + 1,
                 d = a + static_cast<std::uint32_t>(nx);
      // Counter-clockwise seen from above: face normals point up, to the water's side.
      triangles.insert(triangles.end(), { a, b, c, a, c, d });
    }
  }
  return std::make_shared<TriangleBoundary>(std::move(points), std::move(triangles));
}

double triangulatedHeight(const HeightField& ground, double x, double y)
{
  const int nx = ground.nodesX(), ny = ground.nodesY();
  double origin[2], spacing[2];
  ground.grid(origin, spacing);
  const double u = std::clamp((x - origin[0]) / spacing[0], 0.0, nx - 1.0);
  const double v = std::clamp((y - origin[1]) / spacing[1], 0.0, ny - 1.0);
  const int i = std::min(static_cast<int>(u), nx - 2), j = std::min(static_cast<int>(v), ny - 2);
  const double fx = u - i, fy = v - j;
  const auto& z = ground.elevation();
  auto at = [&](int a, int b) { return static_cast<double>(z[static_cast<std::size_t>(b) * nx + a]); };
  // Below the diagonal (fx >= fy): triangle (i,j) (i+1,j) (i+1,j+1); above it: (i,j) (i+1,j+1) (i,j+1).
  if (fx >= fy)
  {
    return at(i, j) + fx * (at(i + 1, j) - at(i, j)) + fy * (at(i + 1, j + 1) - at(i + 1, j));
  }
  return at(i, j) + fy * (at(i, j + 1) - at(i, j)) + fx * (at(i + 1, j + 1) - at(i, j + 1));
}
} // namespace parafluid::rain
