#include "OceanExposure.h"
#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>

namespace parafluid::vtk
{
namespace
{

void normalize(double v[3])
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int c = 0; c < 3 && l > 0.0; ++c)
  {
    v[c] /= l;
  }
}

double luminance(const double c[3])
{
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

/// The procedural sky of oceanSky() (without the sun disk, which a few rays cannot sample).
void sky(const OceanExposureScene& s, const double d[3], double out[3])
{
  if (s.hasEnvironment)
  {
    std::copy(s.environmentMean, s.environmentMean + 3, out);
    return;
  }
  const double up = std::max(d[2], 0.0), blend = std::pow(up, 0.45);
  const double sun = std::max(d[0] * s.sun[0] + d[1] * s.sun[1] + d[2] * s.sun[2], 0.0);
  for (int c = 0; c < 3; ++c)
  {
    out[c] = d[2] < 0.0 ? 0.55 * s.horizon[c] : s.horizon[c] + (s.zenith[c] - s.horizon[c]) * blend;
    out[c] += s.sunColor[c] * 0.25 * std::pow(sun, 12.0);
  }
}
} // namespace

double meanWaterLuminance(const OceanExposureScene& s)
{
  double forward[3] = { s.focal[0] - s.eye[0], s.focal[1] - s.eye[1], s.focal[2] - s.eye[2] };
  normalize(forward);
  double right[3] = { forward[1] * s.up[2] - forward[2] * s.up[1], forward[2] * s.up[0] - forward[0] * s.up[2],
                      forward[0] * s.up[1] - forward[1] * s.up[0] };
  normalize(right);
  const double up[3] = { right[1] * forward[2] - right[2] * forward[1], right[2] * forward[0] - right[0] * forward[2],
                         right[0] * forward[1] - right[1] * forward[0] };
  const double halfHeight = std::tan(0.5 * s.viewAngle * kPi / 180.0), halfWidth = halfHeight * s.aspect;
  double sum = 0.0;
  int hits = 0;
  const int nx = 24, ny = 16;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const double u = (2.0 * (i + 0.5) / nx - 1.0) * halfWidth, v = (2.0 * (j + 0.5) / ny - 1.0) * halfHeight;
      double ray[3];
      for (int c = 0; c < 3; ++c)
      {
        ray[c] = forward[c] + u * right[c] + v * up[c];
      }
      normalize(ray);
      if (!(ray[2] < -1e-6) || !(s.eye[2] > s.seaLevel))
      {
        continue; // sky, or seen from below
      }
      const double t = (s.seaLevel - s.eye[2]) / ray[2];
      const double x = s.eye[0] + t * ray[0], y = s.eye[1] + t * ray[1];
      // Flat water: N = +z, V = -ray.
      const double cosine = -ray[2];
      const double fresnel = 0.02 + 0.98 * std::pow(1.0 - cosine, 5.0);
      const double reflected[3] = { ray[0], ray[1], -ray[2] };
      double skyColor[3];
      sky(s, reflected, skyColor);
      const double depth = s.depth ? std::max(s.depth(x, y), 0.0) : 1.0e6;
      const double shallow = std::exp(-depth / s.colorDepth);
      const double lit = (0.35 + 0.65 * std::max(s.sun[2], 0.0)) * s.sunIntensity;
      const double specular =
        s.sunIntensity *
        std::pow(std::max(reflected[0] * s.sun[0] + reflected[1] * s.sun[1] + reflected[2] * s.sun[2], 0.0),
                 s.shininess) *
        fresnel * 4.0;
      double color[3];
      for (int c = 0; c < 3; ++c)
      {
        const double body = s.deepColor[c] + (s.shallowColor[c] - s.deepColor[c]) * shallow;
        color[c] = (1.0 - fresnel) * body * lit + fresnel * skyColor[c] + s.sunColor[c] * specular;
      }
      sum += luminance(color);
      ++hits;
    }
  }
  return hits > 0 ? sum / hits : 0.0;
}
} // namespace parafluid::vtk
