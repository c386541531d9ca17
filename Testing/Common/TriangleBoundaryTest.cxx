#include "parafluid/common/TriangleBoundary.h"
#include "ClosedBoxMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace
{
using parafluid::TriangleBoundary;

/// A z = height(x, y) surface over [0, size]^2 as (cells x cells) quads split into two triangles.
TriangleBoundary heightField(int cells, float size, float (*height)(float, float), bool withNormals = false)
{
  std::vector<float> points;
  std::vector<std::uint32_t> triangles;
  std::vector<float> normals;
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      const float x = size * i / cells, y = size * j / cells;
      points.insert(points.end(), { x, y, height(x, y) });
      normals.insert(normals.end(), { 0.0f, 0.0f, 1.0f });
    }
  }
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      const std::uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
      triangles.insert(triangles.end(), { a, b, d, a, d, c });
    }
  }
  return TriangleBoundary(std::move(points), std::move(triangles), withNormals ? normals : std::vector<float>{});
}

float flat(float, float)
{
  return 0.0f;
}
float wavy(float x, float y)
{
  return 0.1f * std::sin(3.0f * x) * std::cos(2.0f * y);
}

TEST(TriangleBoundary, FindsTheCrossingPointAndSide)
{
  const TriangleBoundary plane = heightField(4, 1.0f, flat);
  const float a[3] = { 0.3f, 0.4f, 0.5f }, b[3] = { 0.3f, 0.4f, -0.5f };
  TriangleBoundary::Crossing c;
  ASSERT_TRUE(plane.firstCrossing(a, b, c));
  EXPECT_NEAR(c.t, 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(c.side * plane.faceNormal(c.triangle)[2], 1.0f); // a is above
  EXPECT_NEAR(c.barycentric[0] + c.barycentric[1] + c.barycentric[2], 1.0f, 1e-6f);
  const float above[3] = { 0.3f, 0.4f, 0.1f };
  EXPECT_FALSE(plane.firstCrossing(a, above, c)) << "a segment that stays on one side crosses nothing";
  const float outside[3] = { 2.0f, 2.0f, 0.5f }, outsideBelow[3] = { 2.0f, 2.0f, -0.5f };
  EXPECT_FALSE(plane.firstCrossing(outside, outsideBelow, c)) << "beside the mesh there is nothing to cross";
}

TEST(TriangleBoundary, CatchesSegmentsThroughSharedEdgesAndVertices)
{
  const TriangleBoundary plane = heightField(4, 1.0f, flat);
  TriangleBoundary::Crossing c;
  const float edgeA[3] = { 0.25f, 0.3f, 0.2f }, edgeB[3] = { 0.25f, 0.3f, -0.2f }; // on a grid line
  EXPECT_TRUE(plane.firstCrossing(edgeA, edgeB, c));
  const float diagonalA[3] = { 0.1f, 0.1f, 0.2f }, diagonalB[3] = { 0.1f, 0.1f, -0.2f }; // on a diagonal
  EXPECT_TRUE(plane.firstCrossing(diagonalA, diagonalB, c));
  const float vertexA[3] = { 0.5f, 0.5f, 0.2f }, vertexB[3] = { 0.5f, 0.5f, -0.2f }; // through a vertex
  EXPECT_TRUE(plane.firstCrossing(vertexA, vertexB, c));
}

TEST(TriangleBoundary, GridIndexAgreesWithTestingEveryTriangle)
{
  const TriangleBoundary mesh = heightField(60, 2.0f, wavy);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> u(-0.2f, 2.2f), w(-0.3f, 0.3f), step(-0.1f, 0.1f);
  int crossings = 0;
  for (int k = 0; k < 3000; ++k)
  {
    const float a[3] = { u(random), u(random), w(random) };
    const float b[3] = { a[0] + step(random), a[1] + step(random), a[2] + 3.0f * step(random) };
    TriangleBoundary::Crossing indexed;
    const bool hit = mesh.firstCrossing(a, b, indexed);
    // Reference: is a above the surface and b below it, or the reverse (the wavy surface is gentle
    // enough that a short segment crosses it at most once)?
    const float sa = a[2] - wavy(a[0], a[1]), sb = b[2] - wavy(b[0], b[1]);
    const bool inside = a[0] > 0.02f && a[0] < 1.98f && a[1] > 0.02f && a[1] < 1.98f && b[0] > 0.02f && b[0] < 1.98f &&
                        b[1] > 0.02f && b[1] < 1.98f;
    // The triangles approximate the sine within 2e-4 at this resolution; skip near-grazing cases.
    if (inside && std::fabs(sa) > 1e-3f && std::fabs(sb) > 1e-3f)
    {
      EXPECT_EQ(hit, sa * sb < 0.0f) << "segment " << k;
      crossings += hit ? 1 : 0;
    }
  }
  EXPECT_GT(crossings, 200);
}

TEST(TriangleBoundary, NearestPointAgreesWithDenseSamplingOfEveryTriangleWithAnyHint)
{
  // A coarse wavy sheet with its edges and corners in reach: points near faces, edges, vertices and
  // beyond the border. The reference samples every triangle on a 200 x 200 barycentric lattice, so
  // it is at most 1 / 200 of a triangle's size from the true distance (and never below it).
  const TriangleBoundary mesh = heightField(4, 1.0f, wavy);
  std::vector<float> points;
  std::mt19937 random(3);
  std::uniform_real_distribution<float> u(-0.15f, 1.15f), w(-0.25f, 0.25f);
  const float radius = 0.3f;
  int found = 0;
  for (int k = 0; k < 300; ++k)
  {
    const float p[3] = { u(random), u(random), w(random) };
    float distance = -1.0f, direction[3];
    const bool near = mesh.nearest(p, radius, distance, direction);
    // Reference: the triangles of the same sheet, sampled.
    double best = 1e30;
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        const float x0 = 0.25f * i, y0 = 0.25f * j, x1 = x0 + 0.25f, y1 = y0 + 0.25f;
        const float corners[2][3][3] = {
          { { x0, y0, wavy(x0, y0) }, { x1, y0, wavy(x1, y0) }, { x1, y1, wavy(x1, y1) } },
          { { x0, y0, wavy(x0, y0) }, { x1, y1, wavy(x1, y1) }, { x0, y1, wavy(x0, y1) } }
        };
        for (const auto& t : corners)
        {
          for (int a = 0; a <= 200; ++a)
          {
            for (int b = 0; a + b <= 200; ++b)
            {
              const double s = a / 200.0, r = b / 200.0;
              double d2 = 0.0;
              for (int c = 0; c < 3; ++c)
              {
                const double q = t[0][c] + s * (t[1][c] - t[0][c]) + r * (t[2][c] - t[0][c]);
                d2 += (p[c] - q) * (p[c] - q);
              }
              best = std::min(best, d2);
            }
          }
        }
      }
    }
    const double reference = std::sqrt(best);
    // Any hint (a near triangle, a far one, none) gives the same answer: it only narrows the search.
    for (std::uint32_t hint : { 0u, 13u, 31u, 1000u })
    {
      float hinted = -1.0f, hintedDirection[3];
      std::uint32_t triangle = 0;
      EXPECT_EQ(mesh.nearest(p, radius, hinted, hintedDirection, &triangle, hint), near) << "point " << k;
      if (near)
      {
        EXPECT_NEAR(hinted, distance, 1e-6f) << "point " << k << " hint " << hint;
      }
    }
    if (reference < radius - 0.01)
    {
      ASSERT_TRUE(near) << "point " << k;
      EXPECT_LE(distance, reference + 1e-5) << "point " << k;
      EXPECT_GE(distance, reference - 0.0025) << "point " << k;
      // The direction leads from the nearest point back to p.
      const float length =
        std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
      EXPECT_NEAR(length, 1.0f, 1e-5f);
      ++found;
    }
    else if (reference > radius + 0.01)
    {
      EXPECT_FALSE(near) << "point " << k;
    }
  }
  EXPECT_GT(found, 150);
}

TEST(TriangleBoundary, PutsParticlesBackAndReflectsTheirVelocityWithDamping)
{
  const TriangleBoundary plane = heightField(2, 1.0f, flat);
  const float from[3] = { 0.5f, 0.5f, 0.01f };
  float to[3] = { 0.52f, 0.5f, -0.03f };
  float v[3] = { 0.4f, 0.0f, -2.0f };
  const float damping = 0.25f, offset = 1e-4f;
  ASSERT_TRUE(plane.resolve(from, to, v, damping, offset));
  EXPECT_GE(to[2], offset * 0.99f) << "back on the side it came from";
  EXPECT_NEAR(to[2], (1.0f - damping) * 0.03f, 1e-5f) << "overshoot reflected and damped";
  EXPECT_NEAR(to[0], 0.52f, 1e-6f) << "tangential motion kept";
  EXPECT_NEAR(v[2], 2.0f * (1.0f - damping), 1e-5f);
  EXPECT_NEAR(v[0], 0.4f, 1e-6f);
  // Moving away from the surface is left alone.
  float away[3] = { 0.5f, 0.5f, 0.02f };
  float up[3] = { 0.0f, 0.0f, 1.0f };
  EXPECT_FALSE(plane.resolve(from, away, up, damping, offset));
  // From below, a particle is kept below.
  const float under[3] = { 0.5f, 0.5f, -0.01f };
  float through[3] = { 0.5f, 0.5f, 0.02f };
  float rising[3] = { 0.0f, 0.0f, 1.0f };
  ASSERT_TRUE(plane.resolve(under, through, rising, 1.0f, offset));
  EXPECT_LE(through[2], -offset * 0.99f);
  EXPECT_NEAR(rising[2], 0.0f, 1e-6f) << "damping 1 removes the normal velocity";
}

TEST(TriangleBoundary, ReflectsVelocityAboutTheInterpolatedVertexNormal)
{
  // A flat mesh whose vertex normals all lean towards +x: the velocity is reflected about them,
  // not about the face normal.
  std::vector<float> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  std::vector<std::uint32_t> triangle = { 0, 1, 2 };
  const float n = 1.0f / std::sqrt(2.0f);
  std::vector<float> normals = { n, 0, n, n, 0, n, n, 0, n };
  const TriangleBoundary leaning(points, triangle, normals);
  const float from[3] = { 0.2f, 0.2f, 0.1f };
  float to[3] = { 0.2f, 0.2f, -0.1f };
  float v[3] = { 0.0f, 0.0f, -1.0f };
  ASSERT_TRUE(leaning.resolve(from, to, v, 0.0f, 1e-5f));
  // v - 2 (v.n) n with n = (1, 0, 1)/sqrt 2: (1, 0, 0).
  EXPECT_NEAR(v[0], 1.0f, 1e-5f);
  EXPECT_NEAR(v[2], 0.0f, 1e-5f);
}

/// The closed surface of the box [lo, hi]^3, two triangles a face, normals pointing out.
TriangleBoundary closedBox(float lo, float hi)
{
  std::vector<float> points;
  std::vector<std::uint32_t> triangles;
  const float from[3] = { lo, lo, lo }, to[3] = { hi, hi, hi };
  parafluid::testing::appendClosedBox(points, triangles, from, to);
  return TriangleBoundary(std::move(points), std::move(triangles));
}

TEST(TriangleBoundary, ParticlesCreepingOverSharpEdgesNeverGetIntoAClosedBox)
{
  // A particle that climbs a face just below a 90 degree edge and steps up and over it: the move
  // passes within rounding of the edge, where the plane of the next face can be met "from behind".
  // Step lengths from 1e-3 h to h, over all twelve edges (by permuting and mirroring axes).
  const float lo = 0.3f, hi = 0.5f, h = 0.02f, offset = 1e-3f * h;
  const TriangleBoundary box = closedBox(lo, hi);
  ASSERT_LT(box.faceNormal(0)[2], 0.0f) << "normals point out of the box";
  std::mt19937 random(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int permutations[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  long hits = 0;
  for (int k = 0; k < 400000; ++k)
  {
    // Canonical frame: on the x = hi face, just under the top edge z = hi, moving up and in.
    const float scale = std::pow(10.0f, -3.0f * u(random));
    const float p[3] = { hi + offset * (0.4f + 2.0f * u(random)), lo + (hi - lo) * u(random),
                         hi - h * scale * u(random) };
    const float d[3] = { -2.0f * h * scale * u(random), h * scale * (u(random) - 0.5f), 2.0f * h * scale * u(random) };
    const int* axes = permutations[k % 6];
    const int flips = (k / 6) % 8;
    float from[3], to[3], v[3];
    for (int a = 0; a < 3; ++a)
    {
      const bool flip = (flips >> a) & 1;
      from[axes[a]] = flip ? lo + hi - p[a] : p[a];
      v[axes[a]] = flip ? -d[a] : d[a];
      to[axes[a]] = from[axes[a]] + v[axes[a]];
    }
    hits += box.resolve(from, to, v, 0.1f, offset) ? 1 : 0;
    const bool inside = to[0] > lo && to[0] < hi && to[1] > lo && to[1] < hi && to[2] > lo && to[2] < hi;
    ASSERT_FALSE(inside) << "move " << k << " got into the box at (" << to[0] << ", " << to[1] << ", " << to[2]
                         << ") from (" << from[0] << ", " << from[1] << ", " << from[2] << ")";
  }
  EXPECT_GT(hits, 100000) << "most moves should run into the box";
}

TEST(TriangleBoundary, RejectsBadMeshes)
{
  EXPECT_THROW(TriangleBoundary({ 0, 0, 0, 1, 0, 0, 0, 1, 0 }, { 0, 1, 3 }), std::invalid_argument);
  EXPECT_THROW(TriangleBoundary({ 0, 0, NAN, 1, 0, 0, 0, 1, 0 }, { 0, 1, 2 }), std::invalid_argument);
  EXPECT_THROW(TriangleBoundary({ 0, 0, 0, 1 }, { 0 }), std::invalid_argument);
  const TriangleBoundary degenerate({ 0, 0, 0, 1, 0, 0, 2, 0, 0 }, { 0, 1, 2 });
  EXPECT_EQ(degenerate.triangleCount(), 0u) << "a zero-area triangle is dropped";
}
} // namespace
