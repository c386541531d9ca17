#include "parafluid/surface/SurfaceMesh.h"

#include <algorithm>
#include <array>
#include <tuple>

namespace parafluid::surface
{
double enclosedVolume(const SurfaceMesh& mesh)
{
  double volume = 0.0;
  const auto& p = mesh.points;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
  {
    const std::size_t a = 3 * mesh.triangles[3 * t], b = 3 * mesh.triangles[3 * t + 1],
                      c = 3 * mesh.triangles[3 * t + 2];
    // Signed volume of the tetrahedron (origin, a, b, c): a . (b x c) / 6.
    volume += (double(p[a]) * (double(p[b + 1]) * p[c + 2] - double(p[b + 2]) * p[c + 1]) +
               double(p[a + 1]) * (double(p[b + 2]) * p[c] - double(p[b]) * p[c + 2]) +
               double(p[a + 2]) * (double(p[b]) * p[c + 1] - double(p[b + 1]) * p[c])) /
              6.0;
  }
  return volume;
}

EdgeDefects edgeDefects(const SurfaceMesh& mesh)
{
  std::vector<std::pair<std::uint64_t, bool>> edges; // (undirected key, stored in reverse direction)
  edges.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint64_t a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
      edges.emplace_back(a < b ? (a << 32 | b) : (b << 32 | a), a > b);
    }
  }
  std::sort(edges.begin(), edges.end());
  EdgeDefects defects;
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i;
    std::size_t forward = 0;
    while (j < edges.size() && edges[j].first == edges[i].first)
    {
      forward += edges[j].second ? 0 : 1;
      ++j;
    }
    const std::size_t uses = j - i;
    if (uses != 2)
    {
      ++defects.unpairedEdges;
    }
    else if (forward != 1)
    {
      ++defects.misorientedEdges;
    }
    i = j;
  }
  return defects;
}

std::size_t unusedVertices(const SurfaceMesh& mesh)
{
  std::vector<char> used(mesh.vertexCount(), 0);
  for (std::uint32_t v : mesh.triangles)
  {
    used[v] = 1;
  }
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
}

std::size_t coincidentVertices(const SurfaceMesh& mesh)
{
  std::vector<std::array<float, 3>> p(mesh.vertexCount());
  for (std::size_t v = 0; v < p.size(); ++v)
  {
    p[v] = { mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2] };
  }
  std::sort(p.begin(), p.end());
  std::size_t same = 0;
  for (std::size_t v = 1; v < p.size(); ++v)
  {
    same += p[v] == p[v - 1] ? 1 : 0;
  }
  return same;
}
} // namespace parafluid::surface
