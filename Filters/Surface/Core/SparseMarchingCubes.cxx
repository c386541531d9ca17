#include "parafluid/surface/SparseMarchingCubes.h"

#include "parafluid/surface/MarchingCubesCases.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace parafluid::surface
{
namespace
{
constexpr int B = SparseDensityField::BlockPoints;
constexpr int BlockSize = SparseDensityField::BlockSize;
// A block's values with a border: local point indices -1 .. B + 1 on each axis (gradients at the
// block's upper face need the point two beyond its last).
constexpr int P = B + 3;
constexpr std::uint16_t NoVertex = 0xFFFF;

int padded(int i, int j, int k)
{
  return ((k + 1) * P + (j + 1)) * P + (i + 1);
}

// Copies block b's values and its neighbours' border points into `out` (P^3 values).
void gatherPadded(const SparseDensityField& field, std::size_t b, float* out)
{
  int bc[3];
  field.blockCoordinates(b, bc);
  const float* neighbours[27];
  float fill[27];
  for (int dz = -1; dz <= 1; ++dz)
  {
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        const std::int64_t nb = field.findBlock(bc[0] + dx, bc[1] + dy, bc[2] + dz);
        const int slot = (dz + 1) * 9 + (dy + 1) * 3 + (dx + 1);
        neighbours[slot] = nb < 0 ? nullptr : field.values(static_cast<std::size_t>(nb));
        // A block without values lies wholly on one side (the field never reads one beside the
        // surface); its smallest value stands in. A missing block is zero.
        fill[slot] = nb < 0 ? 0.0f : field.minimum(static_cast<std::size_t>(nb));
      }
    }
  }
  for (int k = -1; k <= B + 1; ++k)
  {
    const int oz = k < 0 ? -1 : (k >= B ? 1 : 0);
    const int lz = k - oz * B;
    for (int j = -1; j <= B + 1; ++j)
    {
      const int oy = j < 0 ? -1 : (j >= B ? 1 : 0);
      const int ly = j - oy * B;
      for (int i = -1; i <= B + 1; ++i)
      {
        const int ox = i < 0 ? -1 : (i >= B ? 1 : 0);
        const int lx = i - ox * B;
        const float* block = neighbours[(oz + 1) * 9 + (oy + 1) * 3 + (ox + 1)];
        out[padded(i, j, k)] = block ? block[(lz * B + ly) * B + lx] : fill[(oz + 1) * 9 + (oy + 1) * 3 + (ox + 1)];
      }
    }
  }
}

int cellCase(const float* v, int i, int j, int k, float iso)
{
  int pattern = 0;
  for (int c = 0; c < 8; ++c)
  {
    if (v[padded(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))] > iso)
    {
      pattern |= 1 << c;
    }
  }
  return pattern;
}

const int Step[3] = { 1, P, P* P };

} // namespace

SurfaceMesh sparseMarchingCubes(const SparseDensityField& field, bool normals, MarchingCubesStatistics* statistics)
{
  const float iso = static_cast<float>(field.isoValue());
  if (!(iso > 0.0f) || !std::isfinite(iso))
  {
    throw std::invalid_argument("the iso value must be positive (phi is zero far from the particles)");
  }
  const auto& cases = marchingCubesCases();
  const std::size_t nBlocks = field.blockCount();
  std::vector<std::int32_t> surfaceIndex(nBlocks, -1);
  std::vector<std::uint32_t> surfaceBlocks;
  for (std::size_t b = 0; b < nBlocks; ++b)
  {
    if (field.surfaceBlock(b))
    {
      surfaceIndex[b] = static_cast<std::int32_t>(surfaceBlocks.size());
      surfaceBlocks.push_back(static_cast<std::uint32_t>(b));
    }
  }
  const std::size_t nSurface = surfaceBlocks.size();
  const long long surfaceCount = static_cast<long long>(nSurface);
  std::vector<std::size_t> vertexStart(nSurface + 1, 0), triangleStart(nSurface + 1, 0);
  std::vector<std::uint16_t> edgeVertex(nSurface * 3 * BlockSize, NoVertex);

  // Pass 1: number the crossed edges each block owns, and count its triangles.
#pragma omp parallel
  {
    std::vector<float> v(P * P * P);
#pragma omp for schedule(dynamic, 8)
    for (long long s = 0; s < surfaceCount; ++s)
    {
      gatherPadded(field, surfaceBlocks[s], v.data());
      std::uint16_t* map = edgeVertex.data() + static_cast<std::size_t>(s) * 3 * BlockSize;
      std::uint32_t vertices = 0, triangles = 0;
      for (int k = 0; k < B; ++k)
      {
        for (int j = 0; j < B; ++j)
        {
          for (int i = 0; i < B; ++i)
          {
            const int p = padded(i, j, k);
            const bool in = v[p] > iso;
            for (int a = 0; a < 3; ++a)
            {
              if ((v[p + Step[a]] > iso) != in)
              {
                map[a * BlockSize + (k * B + j) * B + i] = static_cast<std::uint16_t>(vertices++);
              }
            }
            triangles += cases[cellCase(v.data(), i, j, k, iso)].triangleCount;
          }
        }
      }
      vertexStart[s + 1] = vertices;
      triangleStart[s + 1] = triangles;
    }
  }
  for (std::size_t s = 0; s < nSurface; ++s)
  {
    vertexStart[s + 1] += vertexStart[s];
    triangleStart[s + 1] += triangleStart[s];
  }
  SurfaceMesh mesh;
  mesh.points.resize(3 * vertexStart[nSurface]);
  if (normals)
  {
    mesh.normals.resize(3 * vertexStart[nSurface]);
  }
  mesh.triangles.resize(3 * triangleStart[nSurface]);
  if (mesh.vertexCount() >= std::numeric_limits<std::uint32_t>::max())
  {
    throw std::invalid_argument("the surface has more than 2^32 vertices; raise the cell size");
  }
  const double c = field.cellSize();
  const double* origin = field.origin();

  // Pass 2: vertices (and normals), and triangles that look up the vertices of edges owned by
  // this block or by the blocks above it.
#pragma omp parallel
  {
    std::vector<float> v(P * P * P);
#pragma omp for schedule(dynamic, 8)
    for (long long s = 0; s < surfaceCount; ++s)
    {
      const std::size_t b = surfaceBlocks[s];
      gatherPadded(field, b, v.data());
      int bc[3];
      field.blockCoordinates(b, bc);
      const std::uint16_t* map = edgeVertex.data() + static_cast<std::size_t>(s) * 3 * BlockSize;
      std::size_t w = vertexStart[s];
      for (int k = 0; k < B; ++k)
      {
        for (int j = 0; j < B; ++j)
        {
          for (int i = 0; i < B; ++i)
          {
            const int p = padded(i, j, k);
            for (int a = 0; a < 3; ++a)
            {
              if (map[a * BlockSize + (k * B + j) * B + i] == NoVertex)
              {
                continue;
              }
              const int q = p + Step[a];
              // Kept off the edge's ends, so that vertices of different edges never coincide.
              const float t = std::min(0.999f, std::max(0.001f, (iso - v[p]) / (v[q] - v[p])));
              const int local[3] = { i, j, k };
              for (int d = 0; d < 3; ++d)
              {
                const double cells = B * bc[d] + local[d] + (d == a ? t : 0.0f);
                mesh.points[3 * w + d] = static_cast<float>(origin[d] + c * cells);
              }
              if (normals)
              {
                float g[3];
                for (int d = 0; d < 3; ++d)
                {
                  const float g0 = v[p + Step[d]] - v[p - Step[d]];
                  const float g1 = v[q + Step[d]] - v[q - Step[d]];
                  g[d] = -(g0 + t * (g1 - g0));
                }
                float length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
                if (!(length > 0.0f))
                {
                  // A flat spot: fall back to the edge direction, from inside to outside.
                  g[0] = g[1] = g[2] = 0.0f;
                  g[a] = v[p] > iso ? 1.0f : -1.0f;
                  length = 1.0f;
                }
                for (int d = 0; d < 3; ++d)
                {
                  mesh.normals[3 * w + d] = g[d] / length;
                }
              }
              ++w;
            }
          }
        }
      }
      // Vertex offsets and edge maps of this block and the seven above it.
      const std::uint16_t* maps[8];
      std::size_t starts[8];
      for (int n = 0; n < 8; ++n)
      {
        const std::int64_t nb = n == 0
                                  ? static_cast<std::int64_t>(b)
                                  : field.findBlock(bc[0] + (n & 1), bc[1] + ((n >> 1) & 1), bc[2] + ((n >> 2) & 1));
        const std::int32_t ns = nb < 0 ? -1 : surfaceIndex[nb];
        maps[n] = ns < 0 ? nullptr : edgeVertex.data() + static_cast<std::size_t>(ns) * 3 * BlockSize;
        starts[n] = ns < 0 ? 0 : vertexStart[ns];
      }
      std::size_t tw = triangleStart[s];
      for (int k = 0; k < B; ++k)
      {
        for (int j = 0; j < B; ++j)
        {
          for (int i = 0; i < B; ++i)
          {
            const MarchingCubesCase& cell = cases[cellCase(v.data(), i, j, k, iso)];
            for (int e = 0; e < 3 * cell.triangleCount; ++e)
            {
              const int edge = cell.edges[e];
              const int axis = edge / 4;
              int local[3] = { i, j, k };
              local[(axis + 1) % 3] += edge % 2;
              local[(axis + 2) % 3] += (edge / 2) % 2;
              int n = 0;
              for (int d = 0; d < 3; ++d)
              {
                if (local[d] == B)
                {
                  local[d] = 0;
                  n |= 1 << d;
                }
              }
              // Every crossed edge of a polygonised cell belongs to a surface block (see above).
              const std::uint16_t id = maps[n][axis * BlockSize + (local[2] * B + local[1]) * B + local[0]];
              mesh.triangles[3 * tw + e] = static_cast<std::uint32_t>(starts[n] + id);
            }
            tw += cell.triangleCount;
          }
        }
      }
    }
  }
  if (statistics)
  {
    statistics->surfaceBlocks = nSurface;
    statistics->bytes = surfaceIndex.capacity() * sizeof(std::int32_t) +
                        surfaceBlocks.capacity() * sizeof(std::uint32_t) +
                        (vertexStart.capacity() + triangleStart.capacity()) * sizeof(std::size_t) +
                        edgeVertex.capacity() * sizeof(std::uint16_t);
  }
  return mesh;
}
} // namespace parafluid::surface
