#pragma once
// Test and benchmark scenes' obstacles: an axis-aligned box as a closed triangle mesh.
#include <cstdint>
#include <vector>

namespace parafluid::testing
{
/// Appends the box lo..hi to a mesh's arrays: 8 vertices, 12 triangles (two a face, the -z face
/// first), counter-clockwise seen from outside, so the face normals point out of the box.
inline void appendClosedBox(std::vector<float>& points, std::vector<std::uint32_t>& triangles, const float lo[3],
                            const float hi[3])
{
  const auto first = static_cast<std::uint32_t>(points.size() / 3);
  for (int k = 0; k < 8; ++k)
  {
    points.insert(points.end(), { (k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2] });
  }
  const std::uint32_t quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                                      { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& q : quads)
  {
    triangles.insert(triangles.end(),
                     { first + q[0], first + q[1], first + q[2], first + q[0], first + q[2], first + q[3] });
  }
}
} // namespace parafluid::testing
