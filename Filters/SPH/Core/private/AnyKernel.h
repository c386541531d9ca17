#pragma once
// Internal to the SPH solver: the density kernel chosen at run time, for the lattice sums that set
// a run's constants (particle mass, gradient corrections, the mesh wall's table). Not for pair loops.
#include "parafluid/common/Kernels.h"
#include "parafluid/sph/SPHParameters.h"

namespace parafluid::sph::detail
{
/// W(r) and dW/dr of the density kernel of the given support radius.
struct AnyKernel
{
  DensityKernel kind;
  Poly6Kernel poly6;
  CubicSplineKernel cubic;
  WendlandC2Kernel wendland;
  AnyKernel(DensityKernel kind, float h)
    : kind(kind)
    , poly6(h)
    , cubic(h)
    , wendland(h)
  {
  }
  double value(float r) const
  {
    switch (kind)
    {
      case DensityKernel::Poly6:
        return poly6.valueFromSquared(r * r);
      case DensityKernel::CubicSpline:
        return cubic.value(r);
      default:
        return wendland.value(r);
    }
  }
  double derivative(float r) const
  {
    switch (kind)
    {
      case DensityKernel::Poly6:
        return static_cast<double>(poly6.gradientFactorFromSquared(r * r)) * r;
      case DensityKernel::CubicSpline:
        return cubic.radialDerivative(r);
      default:
        return wendland.radialDerivative(r);
    }
  }
};
} // namespace parafluid::sph::detail
