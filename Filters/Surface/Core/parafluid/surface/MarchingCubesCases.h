#pragma once
// The triangles marching cubes puts in one cell, for each of the 256 inside/outside patterns of
// its corners. The table is not typed in: it is derived at start-up from one rule per cube face,
// so two cells that share a face always cut it the same way and the mesh has no cracks.
//
// Corner c of a cell sits at (c & 1, (c >> 1) & 1, (c >> 2) & 1). Edge e runs along axis e / 4
// from the corner with 0 on that axis; its other two coordinates (u, v), taken in the order
// (axis + 1) % 3, (axis + 2) % 3, are (e % 2, (e / 2) % 2). A corner is "inside" when its value is
// above the iso value; bit c of a case index is set when corner c is inside.
#include <array>
#include <cstdint>

namespace parafluid::surface
{
struct MarchingCubesCase
{
  /// Triangles as edge triples, wound counter-clockwise seen from outside (the side where the
  /// value is below the iso value), so right-handed normals point out of the fluid.
  std::uint8_t triangleCount = 0;
  std::array<std::uint8_t, 3 * 12> edges{};
};

/// The 256 cases (built on first use; thread-safe).
const std::array<MarchingCubesCase, 256>& marchingCubesCases();

/// The two corners an edge joins: the lower one (0 on the edge's axis) first.
void marchingCubesEdgeCorners(int edge, int& lower, int& upper);
} // namespace parafluid::surface
