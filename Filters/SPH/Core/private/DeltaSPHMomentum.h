#pragma once
// δ-SPH's momentum equation for one pair: pressure with Monaghan's tensile correction, artificial
// viscosity and the laminar term's factor, and a particle's pair with its own wall image, as the
// CPU's vectorised force pass and the CUDA backend's both evaluate them.
#include "private/DeltaSPHOwnImage.h"
#include "private/DeltaSPHPairs.h"

namespace parafluid::sph::delta
{
/// The momentum factor F of a pair (a_i += m F grad W_ij): pressure, tensile correction and
/// artificial viscosity. x_ij = (dx, dy, dz), |x_ij|^2 = rr, value = W_ij; particle i's query
/// position and velocity q, vq, its density, 1 / density and p_i / rho_i^2 with its tensile part;
/// j's velocity, density and pressure. With Laminar, `laminar` gets the laminar term's factor L
/// (a_i += m L (dW/dr) / r w_ij, w_ij the pair's relative velocity: see laminarVelocity).
/// `inverseRhoJOut` gets 1 / rho_j, for the caller's difference sum.
template<bool Laminar>
PARAFLUID_HOST_DEVICE __attribute__((always_inline)) inline float momentumFactor(
  float dx, float dy, float dz, float rr, float value, const float* vq, float vxj, float vyj, float vzj, float rhoI,
  float termI, float tensileI, float rhoJ, float pJ, const Constants& k, float* laminar, float* inverseRhoJOut)
{
  const float approach = (vq[0] - vxj) * dx + (vq[1] - vyj) * dy + (vq[2] - vzj) * dz; // v_ij . x_ij
  // One division for the three quotients 1 / rho_j, 1 / (r^2 + eta^2) and 2 / (rho_i + rho_j): a
  // division costs several multiplications in the vector units, and three were the pair loop's
  // bottleneck.
  const float rrEta = rr + k.eta2, sumRho = rhoI + rhoJ;
  const float inverse = 1.0f / (rrEta * sumRho * rhoJ);
  const float inverseRhoJ = inverse * rrEta * sumRho;
  *inverseRhoJOut = inverseRhoJ;
  const float termJ = pJ * inverseRhoJ * inverseRhoJ;
  const float tensileJ = pJ < 0.0f ? -kTensileCoefficient * termJ : 0.0f;
  // Capped at 1: Wendland C2 at h = 2 spacings is so peaked that W(0) / W(spacing) = 5.3, and
  // the uncapped f^4 (800) blows a stretched pair apart instead of holding it at a spacing.
  const float ratio = value * k.inverseWSpacing;
  const float f = ratio < 1.0f ? ratio : 1.0f;
  const float f2 = f * f;
  // Monaghan's viscosity acts on approaching pairs only: -alpha c0 mu_ij / rho_ij with mu_ij =
  // h v_ij.x_ij / (r^2 + eta^2) and rho_ij the pair's mean density.
  const float approaching = approach < 0.0f ? approach : 0.0f;
  const float artificial = -2.0f * k.alpha * k.c0 * k.hSmooth * approaching * inverse * rhoJ;
  if constexpr (Laminar)
  {
    // Morris et al. (1997): nu lap v_i = 2 nu sum_j (m / rho_j) x_ij . grad W_ij / (r^2 + eta^2) v_ij,
    // with x_ij . grad W_ij = r^2 (dW/dr) / r.
    *laminar = k.nu2 * rr * inverse * sumRho;
  }
  return -(k.pressureCorrection * (termI + termJ) + (tensileI + tensileJ) * f2 * f2 + artificial);
}

/// The relative velocity of a pair for the laminar term: v_i - v_j, or with a no-slip wall image
/// (`t`, read only with NoSlipImage) v_i - t v_j.
template<bool NoSlipImage>
PARAFLUID_HOST_DEVICE __attribute__((always_inline)) inline void laminarVelocity(const float* vq, float vxj, float vyj,
                                                                                 float vzj, const float* t, float& wx,
                                                                                 float& wy, float& wz)
{
  wx = vq[0] - (NoSlipImage ? t[0] * vxj : vxj);
  wy = vq[1] - (NoSlipImage ? t[1] * vyj : vyj);
  wz = vq[2] - (NoSlipImage ? t[2] * vzj : vzj);
}

/// Adds to `a` (before the image's mapping back) the change of the momentum sum of particle i (at x
/// with velocity v, density rho, pressure p) against its own image (at q with velocity vq) when
/// that pair takes ownImageGradient.
template<bool Laminar>
PARAFLUID_HOST_DEVICE void addOwnImageForce(const float* q, const float* vq, const float* t, const float* x,
                                            const float* v, float rho, float p, const Constants& k, float* a)
{
  float r = 0.0f;
  const float change = ownImageChange(q, x, k, r);
  if (change == 0.0f)
  {
    return;
  }
  const float dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
  const float term = p / (rho * rho);
  const float tensile = p < 0.0f ? -kTensileCoefficient * term : 0.0f;
  float laminar = 0.0f, inverseRho;
  const float scalar = momentumFactor<Laminar>(dx, dy, dz, dx * dx + dy * dy + dz * dz, WendlandPair(k.w, r).value, vq,
                                               v[0], v[1], v[2], rho, term, tensile, rho, p, k, &laminar, &inverseRho) *
                       k.mass * change;
  a[0] += scalar * dx;
  a[1] += scalar * dy;
  a[2] += scalar * dz;
  if constexpr (Laminar)
  {
    float w[3];
    laminarVelocity<true>(vq, v[0], v[1], v[2], t, w[0], w[1], w[2]);
    for (int d = 0; d < 3; ++d)
    {
      a[d] += laminar * k.mass * change * w[d];
    }
  }
}

} // namespace parafluid::sph::delta
