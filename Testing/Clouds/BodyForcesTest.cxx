// Vorticity confinement (Fedkiw, Stam & Jensen 2001) as the step applies it, in two fused passes
// with omega kept in single precision, against a direct cell-by-cell evaluation of the same
// formula: centred velocity, its curl, the unit gradient of |omega|, epsilon h (N x omega), and
// the mean of the two cells' forces on each interior face.
#include "BodyForces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
using namespace parafluid::clouds;
using Vector = std::array<double, 3>;

// A smooth swirling field with a different pattern on every axis, so a wrong index shows.
void swirl(StaggeredGrid& g)
{
  GridArray* faces[3] = { &g.u, &g.v, &g.w };
  for (int a = 0; a < 3; ++a)
  {
    GridArray& f = *faces[a];
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i)
        {
          const double x = (i + f.offset[0]) * g.h, y = (j + f.offset[1]) * g.h, z = (k + f.offset[2]) * g.h;
          f.at(i, j, k) = std::sin(3.1 * y + 0.7 * a) * std::cos(2.3 * z) + 0.4 * std::cos(4.7 * x * (a + 1)) +
                          0.2 * std::sin(5.0 * x * y + a);
        }
  }
}

// The expected force per cell, straight from the definition.
std::vector<Vector> expectedForce(const StaggeredGrid& g, double epsilon)
{
  const int n[3] = { g.nx, g.ny, g.nz };
  auto cell = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * g.ny + j) * g.nx + i; };
  std::vector<Vector> centre(g.cells()), omega(g.cells()), force(g.cells());
  std::vector<double> magnitude(g.cells());
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        centre[cell(i, j, k)] = { 0.5 * (g.u.at(i, j, k) + g.u.at(i + 1, j, k)),
                                  0.5 * (g.v.at(i, j, k) + g.v.at(i, j + 1, k)),
                                  0.5 * (g.w.at(i, j, k) + g.w.at(i, j, k + 1)) };
  // d f / d axis at a cell: central, one-sided at the walls.
  auto derivative = [&](auto value, int i, int j, int k, int axis)
  {
    int lo[3] = { i, j, k }, hi[3] = { i, j, k };
    lo[axis] = std::max(lo[axis] - 1, 0);
    hi[axis] = std::min(hi[axis] + 1, n[axis] - 1);
    if (hi[axis] == lo[axis])
      return 0.0;
    return (value(cell(hi[0], hi[1], hi[2])) - value(cell(lo[0], lo[1], lo[2]))) / ((hi[axis] - lo[axis]) * g.h);
  };
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        auto c = [&](int component) { return [&, component](std::size_t id) { return centre[id][component]; }; };
        Vector& o = omega[cell(i, j, k)];
        o = { derivative(c(2), i, j, k, 1) - derivative(c(1), i, j, k, 2),
              derivative(c(0), i, j, k, 2) - derivative(c(2), i, j, k, 0),
              derivative(c(1), i, j, k, 0) - derivative(c(0), i, j, k, 1) };
        magnitude[cell(i, j, k)] = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
      }
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        auto m = [&](std::size_t id) { return magnitude[id]; };
        Vector N = { derivative(m, i, j, k, 0), derivative(m, i, j, k, 1), derivative(m, i, j, k, 2) };
        const double length = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
        for (double& component : N)
          component = length < 1e-12 ? 0.0 : component / length;
        const Vector& o = omega[cell(i, j, k)];
        const double s = epsilon * g.h;
        force[cell(i, j, k)] = { s * (N[1] * o[2] - N[2] * o[1]), s * (N[2] * o[0] - N[0] * o[2]),
                                 s * (N[0] * o[1] - N[1] * o[0]) };
      }
  return force;
}
} // namespace

TEST(BodyForces, VorticityConfinementMatchesTheFormulaFaceByFace)
{
  StaggeredGrid g;
  g.resize(9, 7, 6, 0.13);
  swirl(g);
  const StaggeredGrid before = g;
  const double epsilon = 0.8, dt = 0.05;
  const std::vector<Vector> force = expectedForce(before, epsilon);
  detail::ForceScratch scratch;
  detail::addVorticityConfinement(g, epsilon, dt, scratch);

  const GridArray* faces[3] = { &g.u, &g.v, &g.w };
  const GridArray* old[3] = { &before.u, &before.v, &before.w };
  double largest = 0.0;
  for (const Vector& f : force)
    largest = std::max({ largest, std::abs(f[0]), std::abs(f[1]), std::abs(f[2]) });
  ASSERT_GT(largest, 1e-3) << "the test field should swirl";
  int checked = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const GridArray& f = *faces[axis];
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i)
        {
          const int at[3] = { i, j, k };
          const double added = f.at(i, j, k) - old[axis]->at(i, j, k);
          if (at[axis] == 0 || at[axis] == f.dims[axis] - 1)
          {
            EXPECT_EQ(added, 0.0) << "a wall face moved: axis " << axis << " at " << i << " " << j << " " << k;
            continue;
          }
          int below[3] = { i, j, k };
          --below[axis];
          const std::size_t a = (static_cast<std::size_t>(k) * g.ny + j) * g.nx + i;
          const std::size_t b = (static_cast<std::size_t>(below[2]) * g.ny + below[1]) * g.nx + below[0];
          const double expected = dt * 0.5 * (force[a][axis] + force[b][axis]);
          // omega and |omega| are kept in single precision.
          EXPECT_NEAR(added, expected, 2e-6 * dt * largest) << "axis " << axis << " face " << i << " " << j << " " << k;
          ++checked;
        }
  }
  EXPECT_EQ(checked, 8 * 7 * 6 + 9 * 6 * 6 + 9 * 7 * 5);
}

TEST(BodyForces, NoSwirlNoConfinement)
{
  // A uniform wind has no vorticity: the faces keep their values exactly.
  StaggeredGrid g;
  g.resize(6, 5, 4, 0.1);
  std::fill(g.u.values.begin(), g.u.values.end(), 1.5);
  std::fill(g.w.values.begin(), g.w.values.end(), -0.5);
  const StaggeredGrid before = g;
  detail::ForceScratch scratch;
  detail::addVorticityConfinement(g, 2.0, 0.1, scratch);
  EXPECT_EQ(g.u.values, before.u.values);
  EXPECT_EQ(g.v.values, before.v.values);
  EXPECT_EQ(g.w.values, before.w.values);
}
