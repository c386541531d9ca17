#pragma once
// A static triangle mesh that particles cannot cross (a terrain, a container, an obstacle).
// Triangles are bucketed in a uniform grid, so a particle's move is tested only against the
// triangles near the segment it travels in one step. A particle whose segment crosses a triangle
// is put back on the side it came from, its remaining travel is reflected across the triangle's
// plane, and its velocity is reflected about the normal interpolated at the crossing point from the
// vertex normals (so a smooth terrain deflects smoothly), keeping (1 - damping) of the normal speed.
#include "parafluid/common/TriangleMeshView.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace parafluid
{
class TriangleBoundary
{
public:
  /// points: x,y,z per vertex [m]; triangles: three vertex indices each; vertexNormals: x,y,z per
  /// vertex, or empty to use area-weighted averages of the face normals. Degenerate triangles are
  /// dropped. Throws std::invalid_argument for out-of-range indices or non-finite coordinates.
  TriangleBoundary(std::vector<float> points, std::vector<std::uint32_t> triangles,
                   std::vector<float> vertexNormals = {});

  using Crossing = TriangleCrossing;
  /// The first triangle the segment a -> b crosses from one side to the other, or (skin > 0) ends
  /// closer than `skin` to from a's side; t is where it enters that skin. A start point exactly on
  /// a triangle's plane has no side and crosses nothing.
  bool firstCrossing(const float a[3], const float b[3], Crossing& crossing, float skin = 0.0f) const
  {
    return this->view().firstCrossing(a, b, crossing, skin);
  }

  /// Keeps a particle moving from `from` to `to` on from's side of every triangle: on a crossing
  /// `to` becomes the damped reflection of the overshoot (at least `offset` metres off the plane) and
  /// `velocity` is reflected. A move that would end within offset / 2 of a triangle counts as a hit
  /// too, so a particle never comes to rest on a plane, where it would have no side. Returns true
  /// when the particle hit the mesh.
  bool resolve(const float from[3], float to[3], float velocity[3], float damping, float offset) const
  {
    return this->view().resolve(from, to, velocity, damping, offset);
  }

  /// The point of the mesh nearest to p, if one lies within `radius` [m]: its distance, the unit
  /// vector from it to p (the face's normal, turned towards p, when p lies on the mesh) and, when
  /// asked, the triangle it lies on. A particle's wall in the SPH's sums.
  bool nearest(const float p[3], float radius, float& distance, float direction[3],
               std::uint32_t* triangle = nullptr) const
  {
    return this->view().nearest(p, radius, distance, direction, triangle, std::numeric_limits<std::uint32_t>::max());
  }
  /// The same, told a triangle that is probably near (the last one found for a particle that has
  /// moved a little): the search then covers only what lies as near as that triangle does.
  bool nearest(const float p[3], float radius, float& distance, float direction[3], std::uint32_t* triangle,
               std::uint32_t hint) const
  {
    return this->view().nearest(p, radius, distance, direction, triangle, hint);
  }

  std::size_t triangleCount() const { return this->Triangles.size() / 3; }
  const float* bounds() const { return this->Grid.bounds; }
  /// Unit normal of triangle t (right-handed in its vertex order).
  const float* faceNormal(std::uint32_t t) const { return &this->FaceNormals[3 * t]; }
  /// The queries over this mesh's arrays (valid while it lives).
  TriangleMeshView view() const;
  /// The arrays a view reads, for a copy on another device (the CUDA backend's).
  const std::vector<float>& points() const { return this->Points; }
  const std::vector<std::uint32_t>& triangles() const { return this->Triangles; }
  const std::vector<float>& vertexNormals() const { return this->VertexNormals; }
  const std::vector<float>& faceNormals() const { return this->FaceNormals; }
  const std::vector<std::uint32_t>& cellStart() const { return this->CellStart; }
  const std::vector<std::uint32_t>& cellTriangles() const { return this->CellTriangles; }
  const TriangleGrid& grid() const { return this->Grid; }

private:
  void buildGrid();
  void triangleBox(std::size_t t, float lo[3], float hi[3]) const;

  std::vector<float> Points;
  std::vector<std::uint32_t> Triangles;
  std::vector<float> VertexNormals;
  std::vector<float> FaceNormals;
  TriangleGrid Grid;
  std::vector<std::uint32_t> CellStart; // triangles of cell c: CellTriangles[CellStart[c] .. CellStart[c+1])
  std::vector<std::uint32_t> CellTriangles;
};
} // namespace parafluid
