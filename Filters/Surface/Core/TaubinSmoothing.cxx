#include "parafluid/surface/TaubinSmoothing.h"

#include <algorithm>

namespace parafluid::surface
{
namespace
{
// Edge neighbours of each vertex as a compressed row list.
void vertexNeighbours(std::size_t nVertices, const std::vector<std::uint32_t>& triangles,
                      std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& neighbours)
{
  start.assign(nVertices + 1, 0);
  for (std::uint32_t v : triangles)
  {
    start[v + 1] += 2;
  }
  for (std::size_t v = 0; v < nVertices; ++v)
  {
    start[v + 1] += start[v];
  }
  neighbours.resize(start[nVertices]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = triangles[t + k];
      neighbours[fill[a]++] = triangles[t + (k + 1) % 3];
      neighbours[fill[a]++] = triangles[t + (k + 2) % 3];
    }
  }
  // Each neighbour appears twice around a manifold vertex; keep it once.
  std::uint32_t w = 0;
  for (std::size_t v = 0; v < nVertices; ++v)
  {
    const auto first = neighbours.begin() + start[v], last = neighbours.begin() + start[v + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    const std::uint32_t begin = w;
    for (auto it = first; it != end; ++it)
    {
      neighbours[w++] = *it;
    }
    start[v] = begin;
  }
  start[nVertices] = w;
  neighbours.resize(w);
}
} // namespace

void taubinSmooth(std::vector<float>& points, const std::vector<std::uint32_t>& triangles, int iterations, float lambda,
                  float mu)
{
  if (iterations <= 0 || triangles.empty())
  {
    return;
  }
  const std::size_t n = points.size() / 3;
  std::vector<std::uint32_t> start, neighbours;
  vertexNeighbours(n, triangles, start, neighbours);
  std::vector<float> next(points.size());
  const long long count = static_cast<long long>(n);
  for (int step = 0; step < 2 * iterations; ++step)
  {
    const float factor = (step % 2 == 0) ? lambda : mu;
#pragma omp parallel for schedule(static)
    for (long long v = 0; v < count; ++v)
    {
      const std::uint32_t b = start[v], e = start[v + 1];
      for (int d = 0; d < 3; ++d)
      {
        const float here = points[3 * v + d];
        if (b == e)
        {
          next[3 * v + d] = here;
          continue;
        }
        float sum = 0.0f;
        for (std::uint32_t k = b; k < e; ++k)
        {
          sum += points[3 * static_cast<std::size_t>(neighbours[k]) + d];
        }
        next[3 * v + d] = here + factor * (sum / static_cast<float>(e - b) - here);
      }
    }
    points.swap(next);
  }
}
} // namespace parafluid::surface
