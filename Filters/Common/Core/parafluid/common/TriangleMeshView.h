#pragma once
// The geometric queries of a TriangleBoundary over plain arrays, so the CPU (TriangleBoundary) and
// the GPU (the CUDA backend, over device copies of the same arrays) run one code: the first
// crossing of a segment, the bounce that keeps a particle on its side, and the nearest point.
// The arrays are owned elsewhere; a view is cheap to copy (it is passed to GPU kernels by value).
#include "parafluid/common/HostDevice.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace parafluid
{
/// The uniform grid the triangles are bucketed in: cells of cellSize from origin, dims of them.
struct TriangleGrid
{
  float bounds[6] = { 0, 0, 0, 0, 0, 0 }; // of every triangle [m]
  float origin[3] = { 0, 0, 0 };
  float cellSize = 1.0f;
  int dims[3] = { 1, 1, 1 };

  /// The cells the box lo..hi overlaps (clamped to the grid); false when it misses the bounds.
  PARAFLUID_HOST_DEVICE bool cellRange(const float lo[3], const float hi[3], int first[3], int last[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      if (hi[a] < this->bounds[2 * a] || lo[a] > this->bounds[2 * a + 1])
      {
        return false;
      }
      const double f = std::floor((static_cast<double>(lo[a]) - this->origin[a]) / this->cellSize);
      const double l = std::floor((static_cast<double>(hi[a]) - this->origin[a]) / this->cellSize);
      first[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(this->dims[a] - 1)));
      last[a] = static_cast<int>(std::clamp(l, 0.0, static_cast<double>(this->dims[a] - 1)));
    }
    return true;
  }
};

struct TriangleCrossing
{
  float t = 0.0f; // fraction of the segment at which it crosses
  std::uint32_t triangle = 0;
  float barycentric[3] = { 0, 0, 0 };
  float side = 1.0f; // +1 when the segment starts on the side the face normal points to
};

struct TriangleMeshView
{
  const float* points = nullptr;            // x, y, z per vertex [m]
  const std::uint32_t* triangles = nullptr; // three vertex indices each
  const float* vertexNormals = nullptr;     // x, y, z per vertex (unit or zero)
  const float* faceNormals = nullptr;       // x, y, z per triangle (unit)
  const std::uint32_t* cellStart = nullptr; // triangles of cell c: cellTriangles[cellStart[c] .. cellStart[c+1])
  const std::uint32_t* cellTriangles = nullptr;
  std::uint32_t triangleCount = 0;
  TriangleGrid grid;

  PARAFLUID_HOST_DEVICE const float* faceNormal(std::uint32_t t) const { return this->faceNormals + 3 * t; }

  /// TriangleBoundary::firstCrossing.
  PARAFLUID_HOST_DEVICE bool firstCrossing(const float a[3], const float b[3], TriangleCrossing& crossing,
                                           float skin = 0.0f) const;
  /// TriangleBoundary::resolve.
  PARAFLUID_HOST_DEVICE bool resolve(const float from[3], float to[3], float velocity[3], float damping,
                                     float offset) const;
  /// TriangleBoundary::nearest, with an optional hint (a triangle index >= triangleCount: none).
  PARAFLUID_HOST_DEVICE bool nearest(const float p[3], float radius, float& distance, float direction[3],
                                     std::uint32_t* triangle, std::uint32_t hint) const;
  /// |q - point|^2, point the nearest point of triangle t to q.
  PARAFLUID_HOST_DEVICE double squaredDistanceTo(std::uint32_t t, const double q[3], double point[3]) const;

private:
  PARAFLUID_HOST_DEVICE bool bounce(const float from[3], float to[3], float velocity[3], float damping,
                                    float offset) const;
  PARAFLUID_HOST_DEVICE bool nearestWithin(const float p[3], float radius, float& distance, float direction[3],
                                           std::uint32_t* triangle) const;
  /// Calls f(triangle) for each triangle listed in the cells first..last (once per cell it is in).
  template<class F>
  PARAFLUID_HOST_DEVICE void forEachTriangleIn(const int first[3], const int last[3], F&& f) const
  {
    for (int k = first[2]; k <= last[2]; ++k)
    {
      for (int j = first[1]; j <= last[1]; ++j)
      {
        for (int i = first[0]; i <= last[0]; ++i)
        {
          const std::size_t c = static_cast<std::size_t>(i) +
                                static_cast<std::size_t>(this->grid.dims[0]) *
                                  (static_cast<std::size_t>(j) + static_cast<std::size_t>(this->grid.dims[1]) * k);
          for (std::uint32_t e = this->cellStart[c]; e < this->cellStart[c + 1]; ++e)
          {
            f(this->cellTriangles[e]);
          }
        }
      }
    }
  }
};

namespace triangle_mesh_detail
{
PARAFLUID_HOST_DEVICE inline void subtract(const float* a, const float* b, double* out)
{
  for (int k = 0; k < 3; ++k)
  {
    out[k] = static_cast<double>(a[k]) - b[k];
  }
}
PARAFLUID_HOST_DEVICE inline double dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
PARAFLUID_HOST_DEVICE inline void copy3(const float* from, float* to)
{
  for (int k = 0; k < 3; ++k)
  {
    to[k] = from[k];
  }
}

// The point of triangle (a, b, c) nearest to p: in the face, on an edge or at a vertex, by the
// region of the plane p projects into (tested through the barycentric coordinates' signs).
PARAFLUID_HOST_DEVICE inline void nearestOnTriangle(const double p[3], const double a[3], const double b[3],
                                                    const double c[3], double out[3])
{
  double ab[3], ac[3], ap[3];
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
    ap[k] = p[k] - a[k];
  }
  auto set = [&](const double* from, const double* along, double t)
  {
    for (int k = 0; k < 3; ++k)
    {
      out[k] = from[k] + t * along[k];
    }
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return set(a, ab, 0.0); // vertex a
  }
  double bp[3], cp[3];
  for (int k = 0; k < 3; ++k)
  {
    bp[k] = p[k] - b[k];
    cp[k] = p[k] - c[k];
  }
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return set(b, ab, 0.0); // vertex b
  }
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return set(c, ac, 0.0); // vertex c
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return set(a, ab, d1 / (d1 - d3)); // edge ab
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return set(a, ac, d2 / (d2 - d6)); // edge ac
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    double bc[3];
    for (int k = 0; k < 3; ++k)
    {
      bc[k] = c[k] - b[k];
    }
    return set(b, bc, (d4 - d3) / ((d4 - d3) + (d5 - d6))); // edge bc
  }
  const double sum = va + vb + vc;
  const double v = vb / sum, w = vc / sum;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = a[k] + v * ab[k] + w * ac[k]; // inside the face
  }
}
} // namespace triangle_mesh_detail

PARAFLUID_HOST_DEVICE inline double TriangleMeshView::squaredDistanceTo(std::uint32_t t, const double q[3],
                                                                        double point[3]) const
{
  const float* v0 = this->points + 3 * this->triangles[3 * t];
  const float* v1 = this->points + 3 * this->triangles[3 * t + 1];
  const float* v2 = this->points + 3 * this->triangles[3 * t + 2];
  const double a[3] = { v0[0], v0[1], v0[2] }, b[3] = { v1[0], v1[1], v1[2] }, c[3] = { v2[0], v2[1], v2[2] };
  triangle_mesh_detail::nearestOnTriangle(q, a, b, c, point);
  return (q[0] - point[0]) * (q[0] - point[0]) + (q[1] - point[1]) * (q[1] - point[1]) +
         (q[2] - point[2]) * (q[2] - point[2]);
}

PARAFLUID_HOST_DEVICE inline bool TriangleMeshView::nearest(const float p[3], float radius, float& distance,
                                                            float direction[3], std::uint32_t* triangle,
                                                            std::uint32_t hint) const
{
  if (hint < this->triangleCount)
  {
    // The hint's distance bounds the nearest one's: only the cells that near need a look.
    const double q[3] = { p[0], p[1], p[2] };
    double point[3];
    const double d = std::sqrt(this->squaredDistanceTo(hint, q, point));
    // A little wider than that distance, so rounding cannot drop the hint itself.
    const auto bound = static_cast<float>(d * (1.0 + 1e-5) + 1e-6 * this->grid.cellSize);
    if (bound < radius && this->nearestWithin(p, bound, distance, direction, triangle))
    {
      return true;
    }
  }
  // A first look within one cell's size: a point nearer than that (a particle resting on the mesh)
  // is the nearest of all, since any nearer point lies in the cells that look covered.
  if (radius > this->grid.cellSize && this->nearestWithin(p, this->grid.cellSize, distance, direction, triangle))
  {
    return true;
  }
  return this->nearestWithin(p, radius, distance, direction, triangle);
}

PARAFLUID_HOST_DEVICE inline bool TriangleMeshView::nearestWithin(const float p[3], float radius, float& distance,
                                                                  float direction[3], std::uint32_t* triangle) const
{
  if (this->triangleCount == 0 || !(radius > 0.0f))
  {
    return false;
  }
  const float lo[3] = { p[0] - radius, p[1] - radius, p[2] - radius };
  const float hi[3] = { p[0] + radius, p[1] + radius, p[2] + radius };
  int first[3], last[3];
  if (!this->grid.cellRange(lo, hi, first, last))
  {
    return false;
  }
  const double q[3] = { p[0], p[1], p[2] };
  double best = static_cast<double>(radius) * radius;
  bool found = false;
  double closest[3] = { 0.0, 0.0, 0.0 };
  std::uint32_t bestTriangle = 0;
  this->forEachTriangleIn(first, last,
                          [&](std::uint32_t t)
                          {
                            const float* v0 = this->points + 3 * this->triangles[3 * t];
                            const float* n = this->faceNormal(t);
                            // The plane's distance bounds the triangle's from below: most triangles end here.
                            const double plane = n[0] * (q[0] - v0[0]) + n[1] * (q[1] - v0[1]) + n[2] * (q[2] - v0[2]);
                            if (plane * plane >= best)
                            {
                              return;
                            }
                            double point[3];
                            const double d2 = this->squaredDistanceTo(t, q, point);
                            if (d2 < best)
                            {
                              best = d2;
                              found = true;
                              bestTriangle = t;
                              for (int k = 0; k < 3; ++k)
                              {
                                closest[k] = point[k];
                              }
                            }
                          });
  if (!found)
  {
    return false;
  }
  const double d = std::sqrt(best);
  distance = static_cast<float>(d);
  if (triangle)
  {
    *triangle = bestTriangle;
  }
  if (d > 1e-9 * this->grid.cellSize)
  {
    for (int k = 0; k < 3; ++k)
    {
      direction[k] = static_cast<float>((q[k] - closest[k]) / d);
    }
    return true;
  }
  const float* n = this->faceNormal(bestTriangle);
  const double side = n[0] * (q[0] - closest[0]) + n[1] * (q[1] - closest[1]) + n[2] * (q[2] - closest[2]);
  for (int k = 0; k < 3; ++k)
  {
    direction[k] = side < 0.0 ? -n[k] : n[k];
  }
  return true;
}

PARAFLUID_HOST_DEVICE inline bool TriangleMeshView::firstCrossing(const float a[3], const float b[3],
                                                                  TriangleCrossing& crossing, float skin) const
{
  using triangle_mesh_detail::dot;
  using triangle_mesh_detail::subtract;
  if (this->triangleCount == 0)
  {
    return false;
  }
  // A crossing point lies exactly on a triangle; widen the box a little for points on cell borders.
  const float pad = 1e-6f * this->grid.cellSize + skin;
  const float lo[3] = { std::min(a[0], b[0]) - pad, std::min(a[1], b[1]) - pad, std::min(a[2], b[2]) - pad };
  const float hi[3] = { std::max(a[0], b[0]) + pad, std::max(a[1], b[1]) + pad, std::max(a[2], b[2]) + pad };
  int first[3], last[3];
  if (!this->grid.cellRange(lo, hi, first, last))
  {
    return false;
  }
  // Barycentric tolerance, so a segment through a shared edge is caught by one of the two triangles.
  // Generous (1e-4 of the triangle), so that at a convex edge the face the segment really goes
  // through is found even when rounding puts the point a hair beyond it; otherwise the next face
  // could be met from behind and the particle pushed into the solid.
  constexpr double tolerance = 1e-4;
  bool found = false;
  double bestT = 2.0;
  this->forEachTriangleIn(
    first, last,
    [&](std::uint32_t t)
    {
      const float* p0 = this->points + 3 * this->triangles[3 * t];
      const float* p1 = this->points + 3 * this->triangles[3 * t + 1];
      const float* p2 = this->points + 3 * this->triangles[3 * t + 2];
      const double n[3] = { this->faceNormals[3 * t], this->faceNormals[3 * t + 1], this->faceNormals[3 * t + 2] };
      double da[3], db[3];
      subtract(a, p0, da);
      subtract(b, p0, db);
      const double sa = dot(n, da);
      const double sb = dot(n, db);
      // A point on the plane has no side to keep.
      if (sa == 0.0)
      {
        return;
      }
      const double side = sa > 0.0 ? 1.0 : -1.0;
      const double startDistance = side * sa, endDistance = side * sb;
      if (endDistance >= skin)
      {
        return;
      }
      const double s = startDistance > skin ? (startDistance - skin) / (startDistance - endDistance) : 0.0;
      if (s >= bestT)
      {
        return;
      }
      // Barycentric coordinates of q = a + s (b - a) projected onto the triangle's plane.
      double q[3], e1[3], e2[3], w[3];
      for (int d = 0; d < 3; ++d)
      {
        q[d] = a[d] + s * (static_cast<double>(b[d]) - a[d]);
      }
      double height = 0.0;
      for (int d = 0; d < 3; ++d)
      {
        height += n[d] * (q[d] - p0[d]);
      }
      for (int d = 0; d < 3; ++d)
      {
        w[d] = q[d] - height * n[d] - p0[d];
      }
      subtract(p1, p0, e1);
      subtract(p2, p0, e2);
      const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
      const double w1 = dot(w, e1), w2 = dot(w, e2);
      const double det = d11 * d22 - d12 * d12;
      const double u = (d22 * w1 - d12 * w2) / det;
      const double v = (d11 * w2 - d12 * w1) / det;
      if (u < -tolerance || v < -tolerance || u + v > 1.0 + tolerance)
      {
        return;
      }
      found = true;
      bestT = s;
      crossing.t = static_cast<float>(s);
      crossing.triangle = t;
      crossing.barycentric[0] = static_cast<float>(1.0 - u - v);
      crossing.barycentric[1] = static_cast<float>(u);
      crossing.barycentric[2] = static_cast<float>(v);
      crossing.side = sa > 0.0 ? 1.0f : -1.0f;
    });
  return found;
}

PARAFLUID_HOST_DEVICE inline bool TriangleMeshView::resolve(const float from[3], float to[3], float velocity[3],
                                                            float damping, float offset) const
{
  if (!this->bounce(from, to, velocity, damping, offset))
  {
    return false;
  }
  // The bounces decide sides one plane at a time. Just past a convex edge, rounding can let the
  // plane of the next face be met "from behind" and the particle be pushed into the solid. The net
  // move must cross nothing: if it does, the particle stays where it was (on the fluid side) and
  // its velocity is reflected off the face that the net move would have gone through.
  TriangleCrossing net;
  if (this->firstCrossing(from, to, net))
  {
    triangle_mesh_detail::copy3(from, to);
    const float* face = this->faceNormal(net.triangle);
    const float n[3] = { net.side * face[0], net.side * face[1], net.side * face[2] };
    const float vn = velocity[0] * n[0] + velocity[1] * n[1] + velocity[2] * n[2];
    if (vn < 0.0f)
    {
      for (int d = 0; d < 3; ++d)
      {
        velocity[d] -= (2.0f - damping) * vn * n[d];
      }
    }
  }
  return true;
}

PARAFLUID_HOST_DEVICE inline bool TriangleMeshView::bounce(const float from[3], float to[3], float velocity[3],
                                                           float damping, float offset) const
{
  const float restitution = 1.0f - damping;
  float start[3] = { from[0], from[1], from[2] };
  bool hit = false;
  // A reflected overshoot can cross another triangle (in a corner); a few bounces settle it.
  constexpr int maxBounces = 4;
  for (int bounce = 0; bounce <= maxBounces; ++bounce)
  {
    // A true crossing first; failing that, an end point that would come to rest within the skin.
    TriangleCrossing c;
    if (!this->firstCrossing(start, to, c) && !this->firstCrossing(start, to, c, 0.5f * offset))
    {
      return hit;
    }
    hit = true;
    if (bounce == maxBounces)
    {
      // Still crossing: stay where the last bounce put it, which is on the fluid side.
      triangle_mesh_detail::copy3(start, to);
      return hit;
    }
    const float* face = this->faceNormal(c.triangle);
    const float n[3] = { c.side * face[0], c.side * face[1], c.side * face[2] }; // towards the fluid
    float point[3];
    for (int d = 0; d < 3; ++d)
    {
      point[d] = start[d] + c.t * (to[d] - start[d]);
    }
    // Distances from the plane itself (point lies on the skin, up to offset / 2 above the plane).
    const float* p0 = this->points + 3 * this->triangles[3 * c.triangle];
    const float endHeight = (to[0] - p0[0]) * n[0] + (to[1] - p0[1]) * n[1] + (to[2] - p0[2]) * n[2];
    const float pointHeight = (point[0] - p0[0]) * n[0] + (point[1] - p0[1]) * n[1] + (point[2] - p0[2]) * n[2];
    // Overshoot below the plane is reflected (damped); the end point is left at least offset above.
    const float reflected = endHeight < 0.0f ? -restitution * endHeight : endHeight;
    const float push = std::max(reflected, offset) - endHeight;
    const float lift = std::max(offset - pointHeight, 0.0f);
    for (int d = 0; d < 3; ++d)
    {
      to[d] += push * n[d];
      start[d] = point[d] + lift * n[d];
    }
    // Velocity: reflect about the smooth (interpolated) normal, oriented to the fluid side.
    float smooth[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      const float* vn = this->vertexNormals + 3 * this->triangles[3 * c.triangle + k];
      for (int d = 0; d < 3; ++d)
      {
        smooth[d] += c.barycentric[k] * vn[d];
      }
    }
    float length = std::sqrt(smooth[0] * smooth[0] + smooth[1] * smooth[1] + smooth[2] * smooth[2]);
    float facing = smooth[0] * n[0] + smooth[1] * n[1] + smooth[2] * n[2];
    if (!(length > 1e-6f) || std::fabs(facing) < 0.1f * length)
    {
      triangle_mesh_detail::copy3(n, smooth); // no usable vertex normals here: use the face's
      length = 1.0f;
      facing = 1.0f;
    }
    const float sign = facing < 0.0f ? -1.0f : 1.0f;
    for (int d = 0; d < 3; ++d)
    {
      smooth[d] *= sign / length;
    }
    const float vn = velocity[0] * smooth[0] + velocity[1] * smooth[1] + velocity[2] * smooth[2];
    if (vn < 0.0f)
    {
      for (int d = 0; d < 3; ++d)
      {
        velocity[d] -= (1.0f + restitution) * vn * smooth[d];
      }
    }
  }
  return hit;
}
} // namespace parafluid
