#include "FluidFootprint.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>

namespace parafluid
{
namespace
{
/// Row vector times a key matrix (stored transposed): the math product M x.
std::array<double, 4> transformPoint(const double m[16], const double x[3])
{
  std::array<double, 4> out{};
  for (int c = 0; c < 4; ++c)
  {
    out[c] = x[0] * m[c] + x[1] * m[4 + c] + x[2] * m[8 + c] + m[12 + c];
  }
  return out;
}
} // namespace

FluidFootprint computeFluidFootprint(const FluidFootprintQuery& q)
{
  FluidFootprint result;
  const int width = q.Size[0], height = q.Size[1];
  int rect[4] = { 0, 0, width, height };
  double nearest = DBL_MAX, farthest = 0.0;
  bool behindEye = false;
  double lo[2] = { DBL_MAX, DBL_MAX }, hi[2] = { -DBL_MAX, -DBL_MAX };
  double slope[2] = { 0.0, 0.0 }; // largest |x| / -z and |y| / -z over the grown bounds
  const double r = q.MaxRadius;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[3] = { q.Bounds[(corner & 1) ? 1 : 0] + ((corner & 1) ? r : -r),
                          q.Bounds[(corner & 2) ? 3 : 2] + ((corner & 2) ? r : -r),
                          q.Bounds[(corner & 4) ? 5 : 4] + ((corner & 4) ? r : -r) };
    const auto eye = transformPoint(q.ModelView, x);
    const double distance = -eye[2];
    nearest = std::min(nearest, distance);
    farthest = std::max(farthest, distance);
    if (!q.Parallel && distance <= q.NearDistance)
    {
      behindEye = true;
      continue;
    }
    for (int k = 0; k < 2; ++k)
    {
      slope[k] = distance > 0.0 ? std::max(slope[k], std::abs(eye[k]) / distance) : DBL_MAX;
    }
    const double e[3] = { eye[0], eye[1], eye[2] };
    const auto clip = transformPoint(q.Projection, e);
    for (int k = 0; k < 2; ++k)
    {
      const double ndc = clip[k] / clip[3];
      lo[k] = std::min(lo[k], ndc);
      hi[k] = std::max(hi[k], ndc);
    }
  }
  result.Nearest = nearest;
  result.Farthest = farthest;
  if (farthest <= q.NearDistance && !q.Parallel)
  {
    return result; // all behind the camera
  }
  if (!behindEye)
  {
    const int size[2] = { width, height };
    for (int k = 0; k < 2; ++k)
    {
      const double a = (0.5 * lo[k] + 0.5) * size[k] - q.Margin;
      const double b = (0.5 * hi[k] + 0.5) * size[k] + q.Margin;
      rect[k] = static_cast<int>(std::floor(std::max(0.0, std::min(a, double(size[k])))));
      rect[k + 2] = static_cast<int>(std::ceil(std::max(0.0, std::min(b, double(size[k])))));
    }
  }
  if (rect[2] <= rect[0] || rect[3] <= rect[1])
  {
    return result; // off screen
  }
  result.Visible = true;
  std::copy(rect, rect + 4, result.Rect);
  // The bound on a sphere's box is the vertex shader's tangent-plane extent at the nearest depth
  // and the widest angle.
  const bool allOnScreen = !behindEye && lo[0] >= -1.0 && hi[0] <= 1.0 && lo[1] >= -1.0 && hi[1] <= 1.0;
  if (allOnScreen)
  {
    const double d = nearest + r; // the nearest a centre can be
    const int size[2] = { width, height };
    double largest = 0.0;
    for (int k = 0; k < 2; ++k)
    {
      const double p = q.Projection[5 * k]; // element (k, k)
      const double ndcWidth =
        q.Parallel ? 2.0 * r * p : p * 2.0 * r * d * std::sqrt(1.0 + slope[k] * slope[k]) / (d * d - r * r);
      largest = std::max(largest, 0.5 * ndcWidth * size[k]);
    }
    result.PointSprites = (q.Parallel || nearest > 0.0) && largest + 3.0 <= q.MaxPointSize;
  }
  return result;
}
} // namespace parafluid
