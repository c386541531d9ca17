#include "parafluid/common/TriangleBoundary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace parafluid
{
namespace
{
void subtract(const float* a, const float* b, double* out)
{
  for (int k = 0; k < 3; ++k)
  {
    out[k] = static_cast<double>(a[k]) - b[k];
  }
}
void cross(const double* a, const double* b, double* out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
double dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
// Grids above this many cells get coarser cells instead.
constexpr double kMaxCells = 4.0e6;
} // namespace

TriangleBoundary::TriangleBoundary(std::vector<float> points, std::vector<std::uint32_t> triangles,
                                   std::vector<float> vertexNormals)
  : Points(std::move(points))
{
  if (this->Points.size() % 3 != 0 || triangles.size() % 3 != 0)
  {
    throw std::invalid_argument("boundary mesh: point and triangle arrays must hold triples");
  }
  const std::size_t vertices = this->Points.size() / 3;
  for (float c : this->Points)
  {
    if (!std::isfinite(c))
    {
      throw std::invalid_argument("boundary mesh: a vertex has a NaN or infinite coordinate");
    }
  }
  for (std::uint32_t v : triangles)
  {
    if (v >= vertices)
    {
      throw std::invalid_argument("boundary mesh: triangle vertex index " + std::to_string(v) + " is out of range (" +
                                  std::to_string(vertices) + " vertices)");
    }
  }
  // Face normals; zero-area triangles cannot be crossed and are dropped.
  std::vector<double> accumulated(this->Points.size(), 0.0);
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    const float* p0 = &this->Points[3 * triangles[t]];
    const float* p1 = &this->Points[3 * triangles[t + 1]];
    const float* p2 = &this->Points[3 * triangles[t + 2]];
    double e1[3], e2[3], n[3];
    subtract(p1, p0, e1);
    subtract(p2, p0, e2);
    cross(e1, e2, n);
    const double twiceArea = std::sqrt(dot(n, n));
    const double scale = std::max({ dot(e1, e1), dot(e2, e2), 1e-300 });
    if (!(twiceArea > 1e-12 * scale))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      this->Triangles.push_back(triangles[t + k]);
      this->FaceNormals.push_back(static_cast<float>(n[k] / twiceArea));
      for (int c = 0; c < 3; ++c)
      {
        accumulated[3 * triangles[t + k] + c] += n[c]; // area-weighted: |n| is twice the area
      }
    }
  }
  if (vertexNormals.size() == this->Points.size())
  {
    this->VertexNormals = std::move(vertexNormals);
  }
  else
  {
    this->VertexNormals.assign(this->Points.size(), 0.0f);
    for (std::size_t v = 0; v < vertices; ++v)
    {
      const double* a = &accumulated[3 * v];
      const double length = std::sqrt(dot(a, a));
      for (int c = 0; c < 3 && length > 0.0; ++c)
      {
        this->VertexNormals[3 * v + c] = static_cast<float>(a[c] / length);
      }
    }
  }
  this->buildGrid();
}

void TriangleBoundary::buildGrid()
{
  const std::size_t m = this->triangleCount();
  if (m == 0)
  {
    this->CellStart.assign(2, 0);
    return;
  }
  for (int a = 0; a < 3; ++a)
  {
    this->Grid.bounds[2 * a] = std::numeric_limits<float>::max();
    this->Grid.bounds[2 * a + 1] = std::numeric_limits<float>::lowest();
  }
  double meanExtent = 0.0;
  for (std::size_t t = 0; t < m; ++t)
  {
    float lo[3], hi[3];
    this->triangleBox(t, lo, hi);
    for (int a = 0; a < 3; ++a)
    {
      this->Grid.bounds[2 * a] = std::min(this->Grid.bounds[2 * a], lo[a]);
      this->Grid.bounds[2 * a + 1] = std::max(this->Grid.bounds[2 * a + 1], hi[a]);
    }
    meanExtent += std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  }
  meanExtent /= static_cast<double>(m);
  // Cells about one triangle wide keep the lists short; fewer than kMaxCells keep memory bounded.
  double size = std::max(meanExtent, 1e-6);
  auto cellsFor = [&](double s)
  {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      cells *= std::floor((this->Grid.bounds[2 * a + 1] - this->Grid.bounds[2 * a]) / s) + 1.0;
    }
    return cells;
  };
  while (cellsFor(size) > kMaxCells)
  {
    size *= 1.5;
  }
  this->Grid.cellSize = static_cast<float>(size);
  std::size_t total = 1;
  for (int a = 0; a < 3; ++a)
  {
    this->Grid.origin[a] = this->Grid.bounds[2 * a];
    this->Grid.dims[a] =
      static_cast<int>(std::floor((this->Grid.bounds[2 * a + 1] - this->Grid.bounds[2 * a]) / size)) + 1;
    total *= static_cast<std::size_t>(this->Grid.dims[a]);
  }
  // Two passes (count, then fill) over the cells each triangle's bounding box overlaps.
  this->CellStart.assign(total + 1, 0);
  for (int pass = 0; pass < 2; ++pass)
  {
    std::vector<std::uint32_t> fill;
    if (pass == 1)
    {
      for (std::size_t c = 0; c < total; ++c)
      {
        this->CellStart[c + 1] += this->CellStart[c];
      }
      this->CellTriangles.resize(this->CellStart[total]);
      fill.assign(this->CellStart.begin(), this->CellStart.end() - 1);
    }
    for (std::size_t t = 0; t < m; ++t)
    {
      float lo[3], hi[3];
      this->triangleBox(t, lo, hi);
      int first[3], last[3];
      if (!this->Grid.cellRange(lo, hi, first, last))
      {
        continue; // not for a triangle, which lies within the bounds; keeps first and last defined
      }
      for (int k = first[2]; k <= last[2]; ++k)
      {
        for (int j = first[1]; j <= last[1]; ++j)
        {
          for (int i = first[0]; i <= last[0]; ++i)
          {
            const std::size_t c = static_cast<std::size_t>(i) +
                                  static_cast<std::size_t>(this->Grid.dims[0]) *
                                    (static_cast<std::size_t>(j) + static_cast<std::size_t>(this->Grid.dims[1]) * k);
            if (pass == 0)
            {
              ++this->CellStart[c + 1];
            }
            else
            {
              this->CellTriangles[fill[c]++] = static_cast<std::uint32_t>(t);
            }
          }
        }
      }
    }
  }
}

void TriangleBoundary::triangleBox(std::size_t t, float lo[3], float hi[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = hi[a] = this->Points[3 * this->Triangles[3 * t] + a];
    for (int k = 1; k < 3; ++k)
    {
      const float c = this->Points[3 * this->Triangles[3 * t + k] + a];
      lo[a] = std::min(lo[a], c);
      hi[a] = std::max(hi[a], c);
    }
  }
}

TriangleMeshView TriangleBoundary::view() const
{
  TriangleMeshView v;
  v.points = this->Points.data();
  v.triangles = this->Triangles.data();
  v.vertexNormals = this->VertexNormals.data();
  v.faceNormals = this->FaceNormals.data();
  v.cellStart = this->CellStart.data();
  v.cellTriangles = this->CellTriangles.data();
  v.triangleCount = static_cast<std::uint32_t>(this->triangleCount());
  v.grid = this->Grid;
  return v;
}
} // namespace parafluid
