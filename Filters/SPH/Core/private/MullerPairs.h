#pragma once
// Internal to the SPH solver: the pair terms of Müller et al.'s (2003) forces and their constants
// (SPHForces.cxx says what each term is), the parts every backend evaluates alike.
#include "parafluid/common/HostDevice.h"
#include "parafluid/common/Kernels.h"
#include "parafluid/sph/SPHParameters.h"

#include <cmath>

namespace parafluid::sph::detail
{
struct MullerConstants
{
  float h, h2, minDistance, pressureScale, viscosityScale;
  float laminarScale; // 10 nu m x the spiky gradient's constant (0: no laminar term)
  float eta2;         // keeps 1 / r^2 finite in the laminar term
  float colourScale;  // -6 m x poly6's constant: the colour field's gradient and Laplacian
  float threshold;    // |n| above which a particle is on the surface [1/m]
  float sigma;        // the surface tension [N/m]
};

/// The constants of the force pass for p; withPressure: Müller's WCSPH (its pressure and explicit
/// laminar term), else DFSPH's explicit forces. spikyCorrection and laplacianCorrection: the
/// lattice corrections of the spiky gradient and of the laminar operator.
inline MullerConstants mullerConstants(const SPHParameters& p, bool withPressure, float spikyCorrection,
                                       float laplacianCorrection)
{
  const SpikyKernel spiky(p.smoothingLength);
  const ViscosityKernel viscous(p.smoothingLength);
  const Poly6Kernel poly6(p.smoothingLength);
  MullerConstants k;
  k.h = p.smoothingLength;
  k.h2 = k.h * k.h;
  // Smallest distance divided by; pairs closer than this push along a direction of zero length.
  k.minDistance = 1e-6f * k.h;
  // a_i(pressure) = -sum_j m (p_i + p_j) / (rho_i rho_j) grad W_spiky, grad W = dW/dr r_ij / r,
  // dW/dr = -3 c (h - r)^2, so the pair term is +3 c m (p_i + p_j)/(rho_i rho_j) (h - r)^2 r_ij / r.
  // Müller's paper halves this ((p_i + p_j) / 2): for a linear pressure field that sum returns
  // half the gradient, so the seed method held water up with twice the hydrostatic pressure.
  // Divided by the lattice correction: the spiky gradient of a linear field on the rest lattice
  // (h = 2 spacings) is 0.93 times the field's gradient.
  k.pressureScale = 3.0f * spiky.coefficient * p.particleMass / (1.0f / spikyCorrection);
  // a_i(viscosity) = mu / rho_i sum_j m (v_j - v_i) / rho_j lap W, lap W = lc (h - r).
  k.viscosityScale = p.viscosity * p.particleMass * viscous.laplacianCoefficient;
  // a_i(laminar) = 2 (d + 2) nu sum_j m / rho_j (v_ij . x_ij) / (r^2 + 0.01 (h/2)^2) grad W_ij;
  // explicit here (Müller's WCSPH); DFSPH solves it implicitly (ImplicitViscosity.cxx).
  // The pass divides every sum by rho_i, so the term carries mu = rho0 nu (Morris et al. 1997).
  k.laminarScale = withPressure ? -3.0f * spiky.coefficient * 10.0f * p.kinematicViscosity * p.restDensity *
                                    p.particleMass * laplacianCorrection
                                : 0.0f;
  k.eta2 = 0.01f * 0.25f * k.h2;
  // Colour field c = sum_j m / rho_j W_poly6: grad W = -6 c (h² - r²)² r_ij, lap W = -6 c (h² - r²)(3h² - 7r²).
  k.colourScale = -6.0f * poly6.coefficient * p.particleMass;
  k.threshold = p.surfaceThreshold / p.smoothingLength;
  k.sigma = p.surfaceTension;
  return k;
}

/// The pressure pair term's factor of (q - x_j) at distance r, w = h - r (the particle itself
/// has q - x_j = 0 and adds nothing).
PARAFLUID_HOST_DEVICE inline float mullerPressurePair(const MullerConstants& k, float pi, float pj, float inverseRhoJ,
                                                      float w, float r)
{
  return k.pressureScale * (pi + pj) * inverseRhoJ * w * w / (r > k.minDistance ? r : k.minDistance);
}

/// The laminar term's factor of (q - x_j); approach = (v - v_j) . T (q - x_j), r2 = r^2, w = h - r.
PARAFLUID_HOST_DEVICE inline float mullerLaminarPair(const MullerConstants& k, float approach, float r2,
                                                     float inverseRhoJ, float w, float r)
{
  return k.laminarScale * inverseRhoJ * approach / (r2 + k.eta2) * w * w / (r > k.minDistance ? r : k.minDistance);
}

/// Müller's viscosity's factor of (v_j - v), w = h - r.
PARAFLUID_HOST_DEVICE inline float mullerViscousPair(const MullerConstants& k, float inverseRhoJ, float w)
{
  return k.viscosityScale * inverseRhoJ * w;
}

/// Adds Müller's surface force density -sigma lap(c) n / |n| (per unit of the query's density,
/// times inverseRhoI), only where |n| marks a surface; normal and laplacian are the unscaled
/// colour sums.
PARAFLUID_HOST_DEVICE inline void addColourFieldTension(const MullerConstants& k, const float normal[3],
                                                        float laplacian, float inverseRhoI, float a[3])
{
  const float n[3] = { k.colourScale * normal[0], k.colourScale * normal[1], k.colourScale * normal[2] };
  const float length = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > k.threshold)
  {
    const float scale = -k.sigma * k.colourScale * laplacian / length * inverseRhoI;
    for (int d = 0; d < 3; ++d)
    {
      a[d] += scale * n[d];
    }
  }
}

/// Müller's equation of state p = k (rho - rho0), clamped at 0 when asked.
PARAFLUID_HOST_DEVICE inline float mullerPressure(float rho, float stiffness, float rho0, bool clamp)
{
  const float pressure = stiffness * (rho - rho0);
  return clamp && pressure < 0.0f ? 0.0f : pressure;
}
} // namespace parafluid::sph::detail
