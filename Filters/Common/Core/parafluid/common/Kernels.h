#pragma once
// Smoothing kernels of Müller, Charypar & Gross, "Particle-Based Fluid Simulation for Interactive
// Applications" (SCA 2003). All have compact support radius h and integrate to 1 over R^3.
// Each kernel keeps its normalisation constants so the hot loops only multiply.
#include "parafluid/common/HostDevice.h"
#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>

namespace parafluid
{

/// Poly6: W(r) = 315/(64 π h^9) (h² − r²)³. Used for density: it needs only r², no square root.
struct Poly6Kernel
{
  explicit Poly6Kernel(float h)
    : h2(h * h)
    , coefficient(315.0f / (64.0f * kPiF * std::pow(h, 9.0f)))
  {
  }
  PARAFLUID_HOST_DEVICE float valueFromSquared(float r2) const
  {
    if (r2 >= h2)
    {
      return 0.0f;
    }
    const float d = h2 - r2;
    return coefficient * d * d * d;
  }
  /// dW/dr / r: the gradient with respect to x_i is this times r_ij (no square root needed).
  PARAFLUID_HOST_DEVICE float gradientFactorFromSquared(float r2) const
  {
    if (r2 >= h2)
    {
      return 0.0f;
    }
    const float d = h2 - r2;
    return -6.0f * coefficient * d * d;
  }
  /// ∇²W = −6 c (h² − r²)(3h² − 7r²); negative near the centre, positive towards the rim.
  PARAFLUID_HOST_DEVICE float laplacianFromSquared(float r2) const
  {
    if (r2 >= h2)
    {
      return 0.0f;
    }
    return -6.0f * coefficient * (h2 - r2) * (3.0f * h2 - 7.0f * r2);
  }
  float h2;
  float coefficient;
};

/// Spiky: W(r) = 15/(π h^6) (h − r)³. Its gradient does not vanish at r → 0, so pressure keeps
/// close particles apart (poly6's gradient would let them clump).
struct SpikyKernel
{
  explicit SpikyKernel(float h)
    : h(h)
    , coefficient(15.0f / (kPiF * std::pow(h, 6.0f)))
  {
  }
  PARAFLUID_HOST_DEVICE float value(float r) const
  {
    if (r >= h)
    {
      return 0.0f;
    }
    const float d = h - r;
    return coefficient * d * d * d;
  }
  /// dW/dr; the gradient with respect to x_i is (dW/dr) · r_ij / r.
  PARAFLUID_HOST_DEVICE float radialDerivative(float r) const
  {
    if (r >= h)
    {
      return 0.0f;
    }
    const float d = h - r;
    return -3.0f * coefficient * d * d;
  }
  float h;
  float coefficient;
};

/// Viscosity kernel: W(r) = 15/(2π h³) (−r³/(2h³) + r²/h² + h/(2r) − 1), whose Laplacian
/// ∇²W = 45/(π h^6) (h − r) is positive everywhere, so viscosity only ever damps relative motion.
struct ViscosityKernel
{
  explicit ViscosityKernel(float h)
    : h(h)
    , valueCoefficient(15.0f / (2.0f * kPiF * h * h * h))
    , laplacianCoefficient(45.0f / (kPiF * std::pow(h, 6.0f)))
  {
  }
  PARAFLUID_HOST_DEVICE float value(float r) const
  {
    if (r >= h || r <= 0.0f)
    {
      return 0.0f;
    }
    const float q = r / h;
    return valueCoefficient * (-0.5f * q * q * q + q * q + 0.5f / q - 1.0f);
  }
  PARAFLUID_HOST_DEVICE float laplacian(float r) const { return r >= h ? 0.0f : laplacianCoefficient * (h - r); }
  float h;
  float valueCoefficient;
  float laplacianCoefficient;
};

/// Cubic B-spline (Monaghan 1992) written with the support radius h (q = r/h):
/// W = 8/(π h³) · { 6q³ − 6q² + 1 for q ≤ ½;  2(1 − q)³ for ½ < q ≤ 1 }.
/// The divergence-free solver uses it for density and gradient alike: predicting the density change
/// from the same kernel that measures density is what makes the predicted and the measured density
/// agree. Its gradient peaks at q = 1/3, well inside the neighbour distance of a lattice with h = 2
/// spacings, so compressed pairs are pushed apart harder (no pairing).
struct CubicSplineKernel
{
  explicit CubicSplineKernel(float h)
    : h(h)
    , h2(h * h)
    , inverseH(1.0f / h)
    , coefficient(8.0f / (kPiF * h * h * h))
  {
  }
  PARAFLUID_HOST_DEVICE float value(float r) const
  {
    const float q = r * inverseH;
    if (q >= 1.0f)
    {
      return 0.0f;
    }
    if (q <= 0.5f)
    {
      return coefficient * (6.0f * q * q * (q - 1.0f) + 1.0f);
    }
    const float d = 1.0f - q;
    return coefficient * 2.0f * d * d * d;
  }
  /// dW/dr.
  PARAFLUID_HOST_DEVICE float radialDerivative(float r) const
  {
    const float q = r * inverseH;
    if (q >= 1.0f)
    {
      return 0.0f;
    }
    if (q <= 0.5f)
    {
      return coefficient * inverseH * q * (18.0f * q - 12.0f);
    }
    const float d = 1.0f - q;
    return -6.0f * coefficient * inverseH * d * d;
  }
  float h;
  float h2;
  float inverseH;
  float coefficient;
};

/// Wendland C2 in 3-D (Wendland 1995; Dehnen & Aly 2012), written with the support radius h
/// (q = r/h): W = 21/(2π h³) (1 − q)⁴ (1 + 4q). Positive Fourier transform, so it does not pair
/// particles however many neighbours there are; the kernel of modern weakly compressible SPH
/// (δ-SPH, DualSPHysics).
struct WendlandC2Kernel
{
  PARAFLUID_HOST_DEVICE explicit WendlandC2Kernel(float h)
    : h(h)
    , h2(h * h)
    , inverseH(1.0f / h)
    , coefficient(21.0f / (2.0f * kPiF * h * h * h))
  {
  }
  PARAFLUID_HOST_DEVICE float value(float r) const
  {
    const float q = r * inverseH;
    if (q >= 1.0f)
    {
      return 0.0f;
    }
    const float d = 1.0f - q;
    return coefficient * d * d * d * d * (1.0f + 4.0f * q);
  }
  /// dW/dr = −20 c q (1 − q)³ / h.
  PARAFLUID_HOST_DEVICE float radialDerivative(float r) const
  {
    const float q = r * inverseH;
    if (q >= 1.0f)
    {
      return 0.0f;
    }
    const float d = 1.0f - q;
    return -20.0f * coefficient * inverseH * q * d * d * d;
  }
  /// (dW/dr) / r = −20 c (1 − q)³ / h²: finite at r = 0, so no division in the pair loops.
  PARAFLUID_HOST_DEVICE float gradientFactor(float r) const
  {
    const float d = std::max(1.0f - r * inverseH, 0.0f);
    return -20.0f * coefficient * inverseH * inverseH * d * d * d;
  }
  float h;
  float h2;
  float inverseH;
  float coefficient;
};

/// Which kernel measures density: Müller's poly6 (WCSPH), the cubic spline (DFSPH) or Wendland C2
/// (δ-SPH).
enum class DensityKernel
{
  Poly6,
  CubicSpline,
  WendlandC2
};
} // namespace parafluid
