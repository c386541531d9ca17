#include "parafluid/common/HeightField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace parafluid
{
HeightField::HeightField(std::vector<float> elevation, int nx, int ny, double x0, double y0, double dx, double dy,
                         double seaLevel)
  : Elevation(std::move(elevation))
  , NX(nx)
  , NY(ny)
  , X0(x0)
  , Y0(y0)
  , DX(dx)
  , DY(dy)
  , SeaLevel(seaLevel)
{
  if (nx < 2 || ny < 2)
  {
    throw std::invalid_argument("bathymetry: the height field needs at least 2 x 2 points");
  }
  if (!(dx > 0.0) || !(dy > 0.0) || !std::isfinite(dx + dy + x0 + y0 + seaLevel))
  {
    throw std::invalid_argument("bathymetry: spacing must be positive and origin and sea level finite");
  }
  if (this->Elevation.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny))
  {
    throw std::invalid_argument("bathymetry: expected " + std::to_string(static_cast<long long>(nx) * ny) +
                                " elevations, got " + std::to_string(this->Elevation.size()));
  }
  for (float z : this->Elevation)
  {
    if (!std::isfinite(z))
    {
      throw std::invalid_argument("bathymetry: an elevation is NaN or infinite");
    }
  }
}

HeightField HeightField::fromTriangles(const std::vector<float>& points, const std::vector<std::uint32_t>& triangles,
                                       int nx, int ny, double seaLevel)
{
  if (points.size() < 9 || points.size() % 3 != 0 || triangles.empty() || triangles.size() % 3 != 0)
  {
    throw std::invalid_argument("bathymetry: the terrain surface has no triangles");
  }
  if (nx < 2 || ny < 2)
  {
    throw std::invalid_argument("bathymetry: the raster needs at least 2 x 2 points");
  }
  double lo[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max() };
  double hi[2] = { std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest() };
  float lowest = std::numeric_limits<float>::max();
  for (float v : points)
  {
    if (!std::isfinite(v))
    {
      throw std::invalid_argument("bathymetry: the terrain surface has a NaN or infinite point");
    }
  }
  for (std::size_t p = 0; p < points.size(); p += 3)
  {
    for (int a = 0; a < 2; ++a)
    {
      lo[a] = std::min(lo[a], static_cast<double>(points[p + a]));
      hi[a] = std::max(hi[a], static_cast<double>(points[p + a]));
    }
    lowest = std::min(lowest, points[p + 2]);
  }
  const std::size_t vertices = points.size() / 3;
  for (std::uint32_t v : triangles)
  {
    if (v >= vertices)
    {
      throw std::invalid_argument("bathymetry: a triangle refers to a point that does not exist");
    }
  }
  const double dx = std::max(hi[0] - lo[0], 1e-9) / (nx - 1), dy = std::max(hi[1] - lo[1], 1e-9) / (ny - 1);
  std::vector<float> elevation(static_cast<std::size_t>(nx) * ny, std::numeric_limits<float>::lowest());
  for (std::size_t t = 0; t < triangles.size(); t += 3)
  {
    const float* a = &points[3 * triangles[t]];
    const float* b = &points[3 * triangles[t + 1]];
    const float* c = &points[3 * triangles[t + 2]];
    const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if (std::fabs(det) < 1e-20)
    {
      continue; // vertical or degenerate: covers no area in plan view
    }
    const double minX = std::min({ a[0], b[0], c[0] }), maxX = std::max({ a[0], b[0], c[0] });
    const double minY = std::min({ a[1], b[1], c[1] }), maxY = std::max({ a[1], b[1], c[1] });
    const int i0 = std::max(0, static_cast<int>(std::ceil((minX - lo[0]) / dx - 1e-9)));
    const int i1 = std::min(nx - 1, static_cast<int>(std::floor((maxX - lo[0]) / dx + 1e-9)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((minY - lo[1]) / dy - 1e-9)));
    const int j1 = std::min(ny - 1, static_cast<int>(std::floor((maxY - lo[1]) / dy + 1e-9)));
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double x = lo[0] + i * dx, y = lo[1] + j * dy;
        // Barycentric coordinates in plan view, with a little slack so shared edges leave no gaps.
        const double u = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
        const double v = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
        if (u < -1e-7 || v < -1e-7 || u + v > 1.0 + 1e-7)
        {
          continue;
        }
        const double z = a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2]);
        float& e = elevation[static_cast<std::size_t>(j) * nx + i];
        e = std::max(e, static_cast<float>(z));
      }
    }
  }
  for (float& e : elevation)
  {
    if (e == std::numeric_limits<float>::lowest())
    {
      e = lowest;
    }
  }
  return HeightField(std::move(elevation), nx, ny, lo[0], lo[1], dx, dy, seaLevel);
}

void HeightField::locate(double x, double y, int& i, int& j, double& fx, double& fy) const
{
  // NaN survives std::clamp and its conversion to int is undefined: a NaN coordinate reads the
  // first cell (heightAt and depth then answer NaN themselves).
  const double ux = (x - this->X0) / this->DX, uy = (y - this->Y0) / this->DY;
  const double gx = std::isnan(ux) ? 0.0 : std::clamp(ux, 0.0, static_cast<double>(this->NX - 1));
  const double gy = std::isnan(uy) ? 0.0 : std::clamp(uy, 0.0, static_cast<double>(this->NY - 1));
  i = std::min(static_cast<int>(gx), this->NX - 2);
  j = std::min(static_cast<int>(gy), this->NY - 2);
  fx = gx - i;
  fy = gy - j;
}

double HeightField::heightAt(double x, double y) const
{
  if (std::isnan(x) || std::isnan(y))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  int i, j;
  double fx, fy;
  this->locate(x, y, i, j, fx, fy);
  return (1 - fx) * (1 - fy) * this->elevationAt(i, j) + fx * (1 - fy) * this->elevationAt(i + 1, j) +
         (1 - fx) * fy * this->elevationAt(i, j + 1) + fx * fy * this->elevationAt(i + 1, j + 1);
}

double HeightField::depth(double x, double y) const
{
  return this->SeaLevel - this->heightAt(x, y);
}

void HeightField::depthGradient(double x, double y, double gradient[2]) const
{
  int i, j;
  double fx, fy;
  this->locate(x, y, i, j, fx, fy);
  const double e00 = this->elevationAt(i, j), e10 = this->elevationAt(i + 1, j);
  const double e01 = this->elevationAt(i, j + 1), e11 = this->elevationAt(i + 1, j + 1);
  // Depth falls where the floor rises.
  gradient[0] = -((1 - fy) * (e10 - e00) + fy * (e11 - e01)) / this->DX;
  gradient[1] = -((1 - fx) * (e01 - e00) + fx * (e11 - e10)) / this->DY;
}

void HeightField::bounds(double b[4]) const
{
  b[0] = this->X0;
  b[1] = this->X0 + (this->NX - 1) * this->DX;
  b[2] = this->Y0;
  b[3] = this->Y0 + (this->NY - 1) * this->DY;
}
} // namespace parafluid
