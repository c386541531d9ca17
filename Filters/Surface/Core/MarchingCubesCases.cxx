#include "parafluid/surface/MarchingCubesCases.h"

namespace parafluid::surface
{
namespace
{
int cornerIndex(int x, int y, int z)
{
  return x | (y << 1) | (z << 2);
}

int edgeIndex(int axis, int u, int v)
{
  return axis * 4 + u + 2 * v;
}

void setCoordinate(int c[3], int axis, int value)
{
  c[axis] = value;
}

// Each face of the cube is walked counter-clockwise seen from outside the cube. The iso line
// crosses the face between corners of opposite sides; each crossing is an edge of the cube where
// the walk goes inside -> outside or outside -> inside. A segment runs from an out->in crossing
// to an in->out crossing: then the inside corners lie on the segment's right seen from outside
// the cube, which makes every loop counter-clockwise about the outward surface normal. On a face
// with four crossings (inside corners diagonal) each inside corner is cut off by its own segment:
// the rule depends only on the face's corners, so the neighbouring cell cuts the face alike.
MarchingCubesCase buildCase(int pattern)
{
  int next[12];
  for (int& n : next)
  {
    n = -1;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      // (u, v) in counter-clockwise order seen from +axis; reversed for the face looking to -axis.
      int uv[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
      if (side == 0)
      {
        std::swap(uv[1][0], uv[3][0]);
        std::swap(uv[1][1], uv[3][1]);
      }
      int corner[4];
      bool inside[4];
      for (int k = 0; k < 4; ++k)
      {
        int c[3];
        setCoordinate(c, axis, side);
        setCoordinate(c, ua, uv[k][0]);
        setCoordinate(c, va, uv[k][1]);
        corner[k] = cornerIndex(c[0], c[1], c[2]);
        inside[k] = ((pattern >> corner[k]) & 1) != 0;
      }
      // The cube edge between face corners k and k+1.
      auto faceEdge = [&](int k)
      {
        const int k1 = (k + 1) % 4;
        const int a = corner[k], b = corner[k1];
        const int diff = a ^ b;
        const int edgeAxis = diff == 1 ? 0 : (diff == 2 ? 1 : 2);
        const int lower = a < b ? a : b;
        const int c[3] = { lower & 1, (lower >> 1) & 1, (lower >> 2) & 1 };
        return edgeIndex(edgeAxis, c[(edgeAxis + 1) % 3], c[(edgeAxis + 2) % 3]);
      };
      for (int k = 0; k < 4; ++k)
      {
        // An out->in crossing entering inside corner k1 pairs with the in->out crossing that
        // leaves it, if that is the next edge; with 2 crossings the next crossing is the only one.
        const int k1 = (k + 1) % 4;
        if (inside[k] || !inside[k1])
        {
          continue;
        }
        int m = k1;
        while (inside[(m + 1) % 4])
        {
          m = (m + 1) % 4;
        }
        next[faceEdge(k)] = faceEdge(m);
      }
    }
  }
  MarchingCubesCase result;
  bool used[12] = {};
  int count = 0;
  for (int start = 0; start < 12; ++start)
  {
    if (next[start] < 0 || used[start])
    {
      continue;
    }
    int loop[12];
    int length = 0;
    for (int e = start; !used[e]; e = next[e])
    {
      used[e] = true;
      loop[length++] = e;
    }
    for (int k = 1; k + 1 < length; ++k)
    {
      result.edges[3 * count + 0] = static_cast<std::uint8_t>(loop[0]);
      result.edges[3 * count + 1] = static_cast<std::uint8_t>(loop[k]);
      result.edges[3 * count + 2] = static_cast<std::uint8_t>(loop[k + 1]);
      ++count;
    }
  }
  result.triangleCount = static_cast<std::uint8_t>(count);
  return result;
}

std::array<MarchingCubesCase, 256> buildTable()
{
  std::array<MarchingCubesCase, 256> table;
  for (int pattern = 0; pattern < 256; ++pattern)
  {
    table[pattern] = buildCase(pattern);
  }
  return table;
}
} // namespace

const std::array<MarchingCubesCase, 256>& marchingCubesCases()
{
  static const std::array<MarchingCubesCase, 256> table = buildTable();
  return table;
}

void marchingCubesEdgeCorners(int edge, int& lower, int& upper)
{
  const int axis = edge / 4;
  int c[3];
  c[axis] = 0;
  c[(axis + 1) % 3] = edge % 2;
  c[(axis + 2) % 3] = (edge / 2) % 2;
  lower = cornerIndex(c[0], c[1], c[2]);
  c[axis] = 1;
  upper = cornerIndex(c[0], c[1], c[2]);
}
} // namespace parafluid::surface
