#include "parafluid/surface/CarpetSurface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace parafluid::surface
{
namespace
{
std::uint32_t spreadBits(std::uint32_t x)
{
  x &= 0xFFFF;
  x = (x | (x << 8)) & 0x00FF00FF;
  x = (x | (x << 4)) & 0x0F0F0F0F;
  x = (x | (x << 2)) & 0x33333333;
  x = (x | (x << 1)) & 0x55555555;
  return x;
}

std::uint32_t compactBits(std::uint32_t x)
{
  x &= 0x55555555;
  x = (x | (x >> 1)) & 0x33333333;
  x = (x | (x >> 2)) & 0x0F0F0F0F;
  x = (x | (x >> 4)) & 0x00FF00FF;
  x = (x | (x >> 8)) & 0x0000FFFF;
  return x;
}
} // namespace

std::uint32_t mortonCode(std::uint32_t i, std::uint32_t j)
{
  return spreadBits(i) | (spreadBits(j) << 1);
}

void mortonDecode(std::uint32_t code, std::uint32_t& i, std::uint32_t& j)
{
  i = compactBits(code);
  j = compactBits(code >> 1);
}

void CarpetSurface::setGrid(double x0, double y0, double x1, double y1, int resolution, std::vector<float> terrain)
{
  if (resolution < 1 || resolution > 65536)
  {
    throw std::invalid_argument("Resolution must be between 1 and 65536 cells, got " + std::to_string(resolution));
  }
  if (!(x1 > x0) || !(y1 > y0) || !std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y0) || !std::isfinite(y1))
  {
    throw std::invalid_argument("the carpet's domain is empty or not finite");
  }
  if (terrain.size() != static_cast<std::size_t>(resolution) * resolution)
  {
    throw std::invalid_argument("the terrain needs one height per cell");
  }
  for (float h : terrain)
  {
    if (!std::isfinite(h))
    {
      throw std::invalid_argument("the terrain has NaN or infinite heights");
    }
  }
  this->X0 = x0;
  this->Y0 = y0;
  this->DX = (x1 - x0) / resolution;
  this->DY = (y1 - y0) / resolution;
  this->N = resolution;
  this->Terrain = std::move(terrain);
  this->reset();
}

void CarpetSurface::reset()
{
  this->Cells.clear();
  this->Levels.clear();
}

float CarpetSurface::terrainAt(std::uint32_t code) const
{
  std::uint32_t i, j;
  mortonDecode(code, i, j);
  return this->Terrain[static_cast<std::size_t>(j) * this->N + i];
}

void CarpetSurface::advance(const float* xyz, std::size_t n, double dt, double fallAcceleration, double minDepth)
{
  if (this->N == 0)
  {
    throw std::logic_error("CarpetSurface::advance before setGrid");
  }
  if (!(dt >= 0.0) || !std::isfinite(fallAcceleration) || !std::isfinite(minDepth))
  {
    throw std::invalid_argument("the carpet needs dt >= 0 and finite FallAcceleration and MinDepth");
  }
  // The highest particle over each cell.
  std::vector<std::pair<std::uint32_t, float>> hits;
  hits.reserve(n);
  for (std::size_t p = 0; p < n; ++p)
  {
    const float x = xyz[3 * p], y = xyz[3 * p + 1], z = xyz[3 * p + 2];
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    {
      throw std::invalid_argument("particle positions contain NaN or infinite values");
    }
    const double fi = std::floor((x - this->X0) / this->DX), fj = std::floor((y - this->Y0) / this->DY);
    if (fi < 0 || fj < 0 || fi >= this->N || fj >= this->N)
    {
      continue;
    }
    hits.emplace_back(mortonCode(static_cast<std::uint32_t>(fi), static_cast<std::uint32_t>(fj)), z);
  }
  std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Cell> next;
  next.reserve(hits.size() / 4 + this->Cells.size());
  std::size_t h = 0, c = 0;
  const float depthLimit = static_cast<float>(minDepth);
  while (h < hits.size() || c < this->Cells.size())
  {
    const std::uint32_t hitCode = h < hits.size() ? hits[h].first : std::numeric_limits<std::uint32_t>::max();
    const std::uint32_t cellCode =
      c < this->Cells.size() ? this->Cells[c].code : std::numeric_limits<std::uint32_t>::max();
    if (h < hits.size() && hitCode <= cellCode)
    {
      float top = hits[h].second;
      for (; h < hits.size() && hits[h].first == hitCode; ++h)
      {
        top = std::max(top, hits[h].second);
      }
      if (cellCode == hitCode)
      {
        ++c; // particles hold this cell up again
      }
      if (top - this->terrainAt(hitCode) > depthLimit)
      {
        next.push_back({ hitCode, top, 0.0f });
      }
      continue;
    }
    // No particles over this cell any more: it falls with constant acceleration (exact for any dt).
    Cell cell = this->Cells[c++];
    cell.height -= static_cast<float>(cell.velocity * dt + 0.5 * fallAcceleration * dt * dt);
    cell.velocity += static_cast<float>(fallAcceleration * dt);
    if (cell.height - this->terrainAt(cell.code) > depthLimit)
    {
      next.push_back(cell);
    }
  }
  this->Cells.swap(next);
  this->buildQuadtree();
}

void CarpetSurface::buildQuadtree()
{
  this->Levels.clear();
  if (this->Cells.empty())
  {
    return;
  }
  std::vector<Node> leaves(this->Cells.size());
  for (std::size_t k = 0; k < this->Cells.size(); ++k)
  {
    const Cell& cell = this->Cells[k];
    leaves[k] = { cell.code, static_cast<std::uint32_t>(k), 0, this->terrainAt(cell.code), cell.height, cell.height };
  }
  this->Levels.push_back(std::move(leaves));
  int levels = 0;
  while ((1 << levels) < this->N)
  {
    ++levels;
  }
  for (int level = 1; level <= levels; ++level)
  {
    const std::vector<Node>& below = this->Levels.back();
    std::vector<Node> nodes;
    for (std::size_t k = 0; k < below.size();)
    {
      Node parent{ below[k].code >> 2, static_cast<std::uint32_t>(k), 0, below[k].minTerrain, below[k].maxFluid, 0.0f };
      double sum = 0.0;
      for (; k < below.size() && (below[k].code >> 2) == parent.code; ++k)
      {
        parent.minTerrain = std::min(parent.minTerrain, below[k].minTerrain);
        parent.maxFluid = std::max(parent.maxFluid, below[k].maxFluid);
        sum += below[k].meanHeight;
        ++parent.childCount;
      }
      parent.meanHeight = static_cast<float>(sum / parent.childCount);
      nodes.push_back(parent);
    }
    this->Levels.push_back(std::move(nodes));
  }
}

std::size_t CarpetSurface::quadtreeNodes() const
{
  std::size_t count = 0;
  for (const auto& level : this->Levels)
  {
    count += level.size();
  }
  return count;
}

double CarpetSurface::meanHeight(int level, int i, int j) const
{
  if (level < 0 || level >= static_cast<int>(this->Levels.size()) || i < 0 || j < 0)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const std::uint32_t code = mortonCode(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
  const auto& nodes = this->Levels[level];
  const auto it =
    std::lower_bound(nodes.begin(), nodes.end(), code, [](const Node& a, std::uint32_t c) { return a.code < c; });
  return (it != nodes.end() && it->code == code) ? it->meanHeight : std::numeric_limits<double>::quiet_NaN();
}

SurfaceMesh CarpetSurface::mesh(std::vector<float>* depth, std::size_t* visitedNodes) const
{
  SurfaceMesh out;
  if (depth)
  {
    depth->clear();
  }
  std::size_t visited = 0;
  // Depth-first from the root; a subtree with no fluid above its lowest terrain is skipped.
  std::vector<std::uint32_t> emitted;
  if (!this->Levels.empty())
  {
    std::vector<std::pair<int, std::uint32_t>> stack;
    const int top = static_cast<int>(this->Levels.size()) - 1;
    for (std::uint32_t k = static_cast<std::uint32_t>(this->Levels[top].size()); k-- > 0;)
    {
      stack.emplace_back(top, k);
    }
    while (!stack.empty())
    {
      const auto [level, index] = stack.back();
      stack.pop_back();
      ++visited;
      const Node& node = this->Levels[level][index];
      if (!(node.maxFluid > node.minTerrain))
      {
        continue;
      }
      if (level == 0)
      {
        emitted.push_back(node.firstChild);
        continue;
      }
      for (std::uint32_t k = node.childCount; k-- > 0;)
      {
        stack.emplace_back(level - 1, node.firstChild + k);
      }
    }
  }
  if (visitedNodes)
  {
    *visitedNodes = visited;
  }
  // Corners shared between cells; a corner's height is the mean of the wet cells around it.
  std::unordered_map<std::uint64_t, std::uint32_t> corners;
  corners.reserve(2 * emitted.size());
  const std::uint64_t stride = static_cast<std::uint64_t>(this->N) + 1;
  auto cornerVertex = [&](std::uint32_t ci, std::uint32_t cj)
  {
    const std::uint64_t key = cj * stride + ci;
    const auto found = corners.find(key);
    if (found != corners.end())
    {
      return found->second;
    }
    double height = 0.0, ground = 0.0;
    int wet = 0, cells = 0;
    for (int dj = -1; dj <= 0; ++dj)
    {
      for (int di = -1; di <= 0; ++di)
      {
        const int i = static_cast<int>(ci) + di, j = static_cast<int>(cj) + dj;
        if (i < 0 || j < 0 || i >= this->N || j >= this->N)
        {
          continue;
        }
        ground += this->Terrain[static_cast<std::size_t>(j) * this->N + i];
        ++cells;
        const double h = this->cellHeight(i, j);
        if (!std::isnan(h))
        {
          height += h;
          ++wet;
        }
      }
    }
    const std::uint32_t v = static_cast<std::uint32_t>(out.vertexCount());
    const float z = static_cast<float>(height / wet);
    out.points.insert(out.points.end(), { static_cast<float>(this->X0 + ci * this->DX),
                                          static_cast<float>(this->Y0 + cj * this->DY), z });
    if (depth)
    {
      depth->push_back(static_cast<float>(z - ground / cells));
    }
    corners.emplace(key, v);
    return v;
  };
  for (std::uint32_t k : emitted)
  {
    std::uint32_t i, j;
    mortonDecode(this->Cells[k].code, i, j);
    const std::uint32_t v00 = cornerVertex(i, j), v10 = cornerVertex(i + 1, j), v11 = cornerVertex(i + 1, j + 1),
                        v01 = cornerVertex(i, j + 1);
    // Counter-clockwise seen from above: normals point up, out of the water.
    out.triangles.insert(out.triangles.end(), { v00, v10, v11, v00, v11, v01 });
  }
  // Vertex normals: area-weighted sums of the triangles' normals.
  out.normals.assign(out.points.size(), 0.0f);
  for (std::size_t t = 0; t < out.triangleCount(); ++t)
  {
    const std::uint32_t a = out.triangles[3 * t], b = out.triangles[3 * t + 1], c = out.triangles[3 * t + 2];
    float e1[3], e2[3];
    for (int d = 0; d < 3; ++d)
    {
      e1[d] = out.points[3 * b + d] - out.points[3 * a + d];
      e2[d] = out.points[3 * c + d] - out.points[3 * a + d];
    }
    const float nrm[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                           e1[0] * e2[1] - e1[1] * e2[0] };
    for (std::uint32_t v : { a, b, c })
    {
      for (int d = 0; d < 3; ++d)
      {
        out.normals[3 * v + d] += nrm[d];
      }
    }
  }
  for (std::size_t v = 0; v < out.vertexCount(); ++v)
  {
    float* nrm = &out.normals[3 * v];
    const float length = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (length > 0.0f)
    {
      nrm[0] /= length, nrm[1] /= length, nrm[2] /= length;
    }
    else
    {
      nrm[0] = nrm[1] = 0.0f, nrm[2] = 1.0f;
    }
  }
  return out;
}
} // namespace parafluid::surface
