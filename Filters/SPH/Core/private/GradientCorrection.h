#pragma once
// Internal to the SPH solver: the kernel gradient correction of a particle (Bonet & Lok 1999) from
// the first moment of its neighbourhood (δ-SPH's; apart from its pair loops, and any solver's to use).
#include "parafluid/common/HostDevice.h"

#include <algorithm>

namespace parafluid::sph::detail
{
// det(C M) of a particle's first moment between which the correction is blended in (see
// gradientCorrection): 1 for a full neighbourhood; on a simple cubic lattice at H = 3 spacings
// 0.83 for a second layer under a free surface and 0.28 for the first.
constexpr double kPartialMoment = 0.95;
constexpr double kFullMoment = 0.97;

/// The first moment M = sum_j V_j (x_j - x_i) (x) grad W_ij (symmetric: xx, xy, xz, yy, yz, zz)
/// of a query's wall image, mapped back to the particle: R M R with R = diag(scale).
PARAFLUID_HOST_DEVICE inline void addImageMoment(const float* moment, const float* scale, float* total)
{
  total[0] += moment[0];
  total[1] += scale[0] * scale[1] * moment[1];
  total[2] += scale[0] * scale[2] * moment[2];
  total[3] += moment[3];
  total[4] += scale[1] * scale[2] * moment[4];
  total[5] += moment[5];
}

/// How full a particle's neighbourhood is, from the determinant of its first moment M (wall images
/// included) and the rest lattice's scalar correction c: 1 where det(c M) >= kFullMoment, 0 up to
/// kPartialMoment (the first two layers under a free surface), linear between.
PARAFLUID_HOST_DEVICE inline double neighbourhoodFullness(double det, double c)
{
  const double full = det * c * c * c;
  return std::min(1.0, std::max(0.0, (full - kPartialMoment) / (kFullMoment - kPartialMoment)));
}

/// The same from M itself (xx, xy, xz, yy, yz, zz).
PARAFLUID_HOST_DEVICE inline float neighbourhoodFullness(const float* m, float c)
{
  const double xx = m[0], xy = m[1], xz = m[2], yy = m[3], yz = m[4], zz = m[5];
  const double det = xx * (yy * zz - yz * yz) + xy * (xz * yz - xy * zz) + xz * (xy * yz - xz * yy);
  return static_cast<float>(neighbourhoodFullness(det, c));
}

/// The gradient correction of a particle from its first moment M (wall images included): L - C I,
/// where L = M^-1 makes the gradient of a linear field exact on any arrangement and C is the rest
/// lattice's scalar correction, which every particle gets anyway. Only for a full neighbourhood:
/// where a free surface cuts the support M loses part of a direction, and the plain gradient,
/// whose p_i + p_j form holds a surface together, is kept; blended in between kPartialMoment and
/// kFullMoment so that a particle nearing a surface is not kicked. (Correcting the second layer
/// under a surface too, from 0.7-0.8, set δ-SPH's still water moving at 4e-2 sqrt(gH).)
PARAFLUID_HOST_DEVICE inline void gradientCorrection(const float* m, float c, float* out)
{
  const double xx = m[0], xy = m[1], xz = m[2], yy = m[3], yz = m[4], zz = m[5];
  const double cofXX = yy * zz - yz * yz, cofXY = xz * yz - xy * zz, cofXZ = xy * yz - xz * yy;
  const double det = xx * cofXX + xy * cofXY + xz * cofXZ;
  const double weight = neighbourhoodFullness(det, c);
  if (weight <= 0.0)
  {
    for (int e = 0; e < 6; ++e)
    {
      out[e] = 0.0f;
    }
    return;
  }
  const double inverse[6] = { cofXX / det,
                              cofXY / det,
                              cofXZ / det,
                              (xx * zz - xz * xz) / det,
                              (xy * xz - xx * yz) / det,
                              (xx * yy - xy * xy) / det };
  for (int e = 0; e < 6; ++e)
  {
    const double lattice = (e == 0 || e == 3 || e == 5) ? c : 0.0;
    out[e] = static_cast<float>(weight * (inverse[e] - lattice));
  }
}

/// a -= E d for the symmetric correction E (xx, xy, xz, yy, yz, zz) and a difference sum d.
PARAFLUID_HOST_DEVICE inline void applyGradientCorrection(const float* e, const float* d, float* a)
{
  a[0] -= e[0] * d[0] + e[1] * d[1] + e[2] * d[2];
  a[1] -= e[1] * d[0] + e[3] * d[1] + e[4] * d[2];
  a[2] -= e[2] * d[0] + e[4] * d[1] + e[5] * d[2];
}
} // namespace parafluid::sph::detail
