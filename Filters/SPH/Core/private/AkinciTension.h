#pragma once
// Internal to the SPH solver: Akinci, Akinci & Teschner's (2013) surface tension (SurfaceTension.cxx
// says how its coefficient is set), the parts every backend evaluates alike.
#include "parafluid/common/HostDevice.h"
#include "parafluid/common/MathConstants.h"
#include "parafluid/sph/SPHParameters.h"

#include <cmath>

namespace parafluid::sph::detail
{
/// Akinci's cohesion kernel C(r) = 32 / (pi h^9) { (h - r)^3 r^3 for h/2 < r <= h;
/// 2 (h - r)^3 r^3 - h^6 / 64 for 0 < r <= h/2 } (negative = repulsive at short range), with its
/// constants taken out of the pair loop.
struct CohesionKernel
{
  explicit CohesionKernel(float h)
    : h(h)
    , coefficient(static_cast<float>(32.0 / (kPi * std::pow(static_cast<double>(h), 9.0))))
    , core(static_cast<float>(std::pow(static_cast<double>(h), 6.0) / 64.0))
  {
  }
  /// C(r) for 0 <= r <= h (0 beyond); branch-free for the vectorised loop.
  PARAFLUID_HOST_DEVICE float operator()(float r) const
  {
    const float e = h - r > 0.0f ? h - r : 0.0f;
    const float d = e * e * e * r * r * r;
    return coefficient * (r > 0.5f * h ? d : 2.0f * d - core);
  }
  float h, coefficient, core;
};

/// Akinci's gamma for these parameters (SurfaceTensionModel Akinci or AkinciCohesion): the two
/// terms together, or the cohesion alone, give a flat interface the surface tension sigma.
float akinciGamma(const SPHParameters& p);
} // namespace parafluid::sph::detail
