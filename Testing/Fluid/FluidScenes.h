// Particle scenes shared by the screen-space fluid benchmark and its test: a lattice ball (with an
// analytic surface to measure depth against) and a dam-break block of fluid on a floor.
#pragma once

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace parafluid_test
{
/// Centres of a cubic lattice (spacing h) inside a ball of radius R about the origin.
inline vtkSmartPointer<vtkPolyData> latticeBall(double R, double h)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  const int n = static_cast<int>(std::ceil(R / h));
  for (int i = -n; i <= n; ++i)
  {
    for (int j = -n; j <= n; ++j)
    {
      for (int k = -n; k <= n; ++k)
      {
        const double x = i * h, y = j * h, z = k * h;
        if (x * x + y * y + z * z <= R * R)
        {
          points->InsertNextPoint(x, y, z);
        }
      }
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

/// Centres of a cubic lattice (spacing h) in a slab facing +z: |x|, |y| <= halfWidth, `layers`
/// deep, centred on z = 0.
inline vtkSmartPointer<vtkPolyData> latticeSlab(double halfWidth, int layers, double h)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  const int n = static_cast<int>(std::floor(halfWidth / h));
  for (int i = -n; i <= n; ++i)
  {
    for (int j = -n; j <= n; ++j)
    {
      for (int k = 0; k < layers; ++k)
      {
        points->InsertNextPoint(i * h, j * h, (k - 0.5 * (layers - 1)) * h);
      }
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

/// Radius of the ball holding the volume n particles of spacing h stand for (n h^3): where the
/// surface of the fluid they sample is.
inline double volumeRadius(vtkIdType n, double h)
{
  return std::cbrt(3.0 * static_cast<double>(n) / (4.0 * 3.14159265358979323846)) * h;
}

/// About `count` particles on a lattice filling a 2 x 1 x 1 block (a dam-break column).
inline vtkSmartPointer<vtkPolyData> damBlock(long count, double& spacing)
{
  spacing = std::cbrt(2.0 / static_cast<double>(count));
  const int nx = static_cast<int>(std::round(2.0 / spacing));
  const int ny = static_cast<int>(std::round(1.0 / spacing));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nx) * ny * ny);
  vtkIdType id = 0;
  for (int i = 0; i < nx; ++i)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int k = 0; k < ny; ++k)
      {
        points->SetPoint(id++, (i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing);
      }
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

/// `block` plus droplets of 2 x 2 x 2 particles (spacing apart) holding `fraction` of its
/// particle count, at random in the air above it (z 1.2 to 2), seeded by `seed`; no point arrays.
inline vtkSmartPointer<vtkPolyData> withDroplets(vtkPolyData* block, double spacing, double fraction, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0.0, 2.0), y(0.0, 1.0), z(1.2, 2.0);
  const vtkIdType n = block->GetNumberOfPoints();
  const vtkIdType drops = static_cast<vtkIdType>(fraction * n / 8);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n + 8 * drops);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, block->GetPoint(i));
  }
  for (vtkIdType d = 0; d < drops; ++d)
  {
    const double c[3] = { x(rng), y(rng), z(rng) };
    for (int k = 0; k < 8; ++k)
    {
      points->SetPoint(n + 8 * d + k, c[0] + (k & 1) * spacing, c[1] + ((k >> 1) & 1) * spacing,
                       c[2] + ((k >> 2) & 1) * spacing);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

/// Gives particles a `velocity` (a swirl about the vertical axis through x = 1, y = 0.5, at
/// 1 rad/s, slowing with height to rest at z = 1) and a `density` [kg/m^3] rising with depth,
/// for the brush strokes.
inline void addSwirl(vtkPolyData* data)
{
  vtkNew<vtkFloatArray> velocity, density;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(data->GetNumberOfPoints());
  density->SetName("density");
  density->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    const double slow = std::max(0.0, 1.0 - x[2]);
    velocity->SetTuple3(i, -(x[1] - 0.5) * slow, (x[0] - 1.0) * slow, 0.0);
    density->SetValue(i, static_cast<float>(1000.0 + 5.0 * (1.0 - x[2]))); // rises with depth
  }
  data->GetPointData()->AddArray(velocity);
  data->GetPointData()->AddArray(density);
}
}
