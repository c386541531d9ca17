#pragma once
// A triangle mesh as flat arrays, what the surface extractors return.
#include <cstdint>
#include <vector>

namespace parafluid::surface
{
struct SurfaceMesh
{
  std::vector<float> points;            // x, y, z per vertex [m]
  std::vector<float> normals;           // unit outward normal per vertex (empty when not computed)
  std::vector<std::uint32_t> triangles; // three vertex indices per triangle, counter-clockwise from outside

  std::size_t vertexCount() const { return this->points.size() / 3; }
  std::size_t triangleCount() const { return this->triangles.size() / 3; }
};

/// Volume enclosed by a closed, outward-oriented mesh [m^3] (divergence theorem; negative when
/// the triangles face inwards).
double enclosedVolume(const SurfaceMesh& mesh);

/// Edge-manifold check: the number of undirected edges not shared by exactly two triangles, and
/// of directed edges used twice in the same direction (a sign of inconsistent orientation). Both
/// are zero for a watertight, consistently oriented mesh.
struct EdgeDefects
{
  std::size_t unpairedEdges = 0;
  std::size_t misorientedEdges = 0;
};
EdgeDefects edgeDefects(const SurfaceMesh& mesh);

/// Number of vertices that no triangle uses, and of vertex pairs at the same position (both are
/// zero when vertices are shared between cells).
std::size_t unusedVertices(const SurfaceMesh& mesh);
std::size_t coincidentVertices(const SurfaceMesh& mesh);
} // namespace parafluid::surface
