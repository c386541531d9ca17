#pragma once
// δ-SPH's pieces shared by its passes (DeltaSPH*.cxx): the constants of a pass, the Wendland pair,
// the candidates' arrays as the vectorised pair loops read them, and the fluid's hydrostatic
// reference.
#include "parafluid/common/HostDevice.h"
#include "parafluid/common/Kernels.h"
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"
#include "private/NeighbourCandidates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace parafluid::sph::delta
{
using detail::CandidateBuffer;

constexpr float kGamma = 7.0f;              // Tait exponent for water (Batchelor 1967; Monaghan 1994)
constexpr float kTensileCoefficient = 0.2f; // Monaghan (2000): R_i = 0.2 |p_i| / rho_i^2 where p_i < 0
constexpr float kTensileExponent = 4.0f;    // ... times (W(r) / W(spacing))^4

enum Channel
{
  VX,
  VY,
  VZ,
  DENSITY,
  PRESSURE,                // the force pass
  FULLNESS = PRESSURE,     // the continuity pass: each particle's neighbourhoodFullness, a step old
  SLOW_DEPARTURE,          // the continuity pass: the slow part of each particle's departure from hydrostatic
  PUSH_X = SLOW_DEPARTURE, // the force pass: DeltaSPHSolver::FullPush, x, y and z
  PUSH_Y,
  PUSH_Z
};

struct Constants
{
  PARAFLUID_HOST_DEVICE explicit Constants(float supportRadius)
    : w(supportRadius)
  {
  }
  float h2;      // support radius squared
  float hSmooth; // the smoothing length of the δ-SPH literature, half the support radius
  float eta2;    // 0.01 hSmooth^2: keeps 1 / r^2 finite
  float mass;
  float c0, alpha, delta, nu2; // 2 nu, times the lattice's Laplacian correction
  float rho0, inverseC0Squared;
  float gravity[3];
  float inverseWSpacing; // 1 / W(particle spacing), for the tensile correction
  WendlandC2Kernel w;
  // The discrete gradient of a linear field on the rest lattice is C times the true one (C = 0.98
  // for Wendland C2 at h = 2 spacings); pressure forces are divided by C so that a resting column
  // carries exactly its weight (see latticeGradientCorrection).
  float pressureCorrection;
  // The pair of a particle and its own wall image (see ownImageGradient): dW/dr at the rest
  // distance of a first layer from its image, one spacing, and that distance.
  float ownImageSlope, ownImageRest;
  // Whether the spiky profile is clearly the stiffer at the rest distance: (H - r)^2 falls off
  // faster than Wendland's q (1 - q)^3 exactly where q = rest / H < 1/2 (supports over 2 spacings),
  // by 13 % at q = 0.45 and 33 % at 0.4. Taken from q < 0.45 on, so that a support of 2 spacings
  // (where both stiffen alike, and the stiffer push is unstable in violent flow) keeps the plain
  // kernel however the spacing computed from the mass rounds.
  bool ownImageStiffened;
  // The gradient correction (SPHParameters::gradientCorrection): its first moments are summed in
  // the continuity pass, and wall images carry hydrostatically extrapolated pressure.
  bool correctGradient;
  bool highPass; // SPHParameters::pushHighPass
};

/// The constants of a pass over the current parameters, the sound speed c0 [m/s], the particle
/// spacing [m] and the lattice corrections of the laminar term and the pressure gradient.
inline Constants makeConstants(const SPHParameters& p, double soundSpeed, float spacing, float laplacianCorrection,
                               float pressureCorrection)
{
  Constants k(p.smoothingLength);
  const float restSpacing = std::min(spacing, 0.99f * p.smoothingLength); // inside the support
  k.h2 = k.w.h2;
  k.hSmooth = 0.5f * p.smoothingLength;
  k.eta2 = 0.01f * 0.25f * k.w.h2;
  k.mass = p.particleMass;
  k.c0 = static_cast<float>(soundSpeed);
  k.alpha = p.artificialViscosity;
  k.delta = p.densityDiffusion;
  // Müller's extra viscosity, when set, joins the physical one here.
  k.nu2 = 2.0f * (p.kinematicViscosity + p.viscosity / p.restDensity) * laplacianCorrection;
  k.rho0 = p.restDensity;
  k.inverseC0Squared = static_cast<float>(1.0 / (soundSpeed * soundSpeed));
  // Gravity along a periodic axis drives a flow and builds no hydrostatic pressure.
  for (int a = 0; a < 3; ++a)
  {
    k.gravity[a] = p.periodic[a] ? 0.0f : p.gravity[a];
  }
  k.inverseWSpacing = 1.0f / k.w.value(restSpacing);
  k.pressureCorrection = pressureCorrection;
  k.ownImageSlope = k.w.radialDerivative(restSpacing);
  k.ownImageRest = restSpacing;
  k.ownImageStiffened = spacing < 0.45f * p.smoothingLength;
  k.correctGradient = p.gradientCorrection;
  k.highPass = p.pushHighPass;
  return k;
}

/// (dW/dr) / r of the Wendland kernel, and the kernel itself, at distance r. (Builtins only: it is
/// inlined into the pair loops' AVX-512 copies, which inline no ordinary function; the CUDA
/// backend's pair loops call it too.)
struct WendlandPair
{
  float gradient, value;
  PARAFLUID_HOST_DEVICE __attribute__((always_inline)) WendlandPair(const WendlandC2Kernel& w, float r)
  {
    const float q = r * w.inverseH;
    const float d = 1.0f - q > 0.0f ? 1.0f - q : 0.0f;
    const float d3 = d * d * d;
    gradient = -20.0f * w.coefficient * w.inverseH * w.inverseH * d3;
    value = w.coefficient * d3 * d * (1.0f + 4.0f * q);
  }
};

/// The candidates within the kernel's support (their buffer positions `hits`) and the buffer's
/// arrays, as raw pointers: the pair loops below are compiled as AVX-512, AVX2 and baseline copies
/// (parafluid/common/SimdDispatch.h), and an AVX-512 copy, tuned for another processor, inlines
/// no ordinary function (GCC requires the same tuning), so they touch no std:: call.
struct PairInput
{
  const float *px, *py, *pz, *vx, *vy, *vz, *rho, *pressure, *fullness, *slowDeparture, *pushY, *pushZ;
  const std::uint32_t* hits;
  std::uint32_t count;
  /// The hits of q, or (image) of a wall image of the particle whose own hits were found last.
  PairInput(CandidateBuffer& c, const float q[3], float h2, bool image)
    : px(c.x.data())
    , py(c.y.data())
    , pz(c.z.data())
    , vx(c.channel[VX].data())
    , vy(c.channel[VY].data())
    , vz(c.channel[VZ].data())
    , rho(c.channel[DENSITY].data())
    , pressure(c.channel[PRESSURE].data())
    , fullness(c.channel[FULLNESS].data())
    , slowDeparture(c.channel[SLOW_DEPARTURE].data())
    , pushY(c.channel[PUSH_Y].data())
    , pushZ(c.channel[PUSH_Z].data())
    , hits(image ? c.imageHits.data() : c.hits.data())
    , count(image ? c.findImageHits(q, h2) : c.padHits(c.findHits(q, h2, false)))
  {
  }
};

/// rho - rho^H(x), up to a constant: rho^H = rho0 (1 + g . x / c0^2), the linearised hydrostatic
/// density the diffusion leaves alone (densityRateBody), of density rho at (x, y, z).
PARAFLUID_HOST_DEVICE inline float departureFromHydrostatic(const Constants& k, float x, float y, float z, float rho)
{
  const float height = k.gravity[0] * x + k.gravity[1] * y + k.gravity[2] * z;
  return rho - k.rho0 - k.rho0 * height * k.inverseC0Squared;
}

/// The same of particle i.
inline float departureFromHydrostatic(const Constants& k, const ParticleState& s, std::size_t i)
{
  return departureFromHydrostatic(k, s.x[i], s.y[i], s.z[i], s.density[i]);
}

/// Tait's equation of state p = B ((rho / rho0)^7 - 1) [Pa], with B = c0^2 rho0 / 7 and 1 / rho0.
PARAFLUID_HOST_DEVICE inline float taitPressure(float rho, float bulk, float inverseRho0)
{
  const float ratio = rho * inverseRho0;
  const float r2 = ratio * ratio;
  return bulk * (r2 * r2 * r2 * ratio - 1.0f);
}

inline double gravityMagnitude(const SPHParameters& p)
{
  return std::sqrt(static_cast<double>(p.gravity[0]) * p.gravity[0] + static_cast<double>(p.gravity[1]) * p.gravity[1] +
                   static_cast<double>(p.gravity[2]) * p.gravity[2]);
}

/// The lowest and highest height against gravity over the particles [m] (+inf and -inf for none).
inline std::array<double, 2> heightRange(const SPHParameters& p, const ParticleState& s)
{
  const double g = gravityMagnitude(p);
  std::array<double, 2> range = { std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const double along = g > 0.0 ? -(s.x[i] * p.gravity[0] + s.y[i] * p.gravity[1] + s.z[i] * p.gravity[2]) / g : 0.0;
    range[0] = std::min(range[0], along);
    range[1] = std::max(range[1], along);
  }
  return range;
}

/// The fluid's height along gravity [m] over a height range, counting its top layer of particles
/// (half a kernel radius).
inline double fluidHeight(const SPHParameters& p, const std::array<double, 2>& range)
{
  return (range[1] >= range[0] ? range[1] - range[0] : 0.0) + 0.5 * p.smoothingLength;
}

inline double fluidHeight(const SPHParameters& p, const ParticleState& s)
{
  return fluidHeight(p, heightRange(p, s));
}

/// The fastest particle's speed [m/s] (0 for none).
inline double fastestSpeed(const ParticleState& s)
{
  double fastest = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    fastest =
      std::max(fastest, std::sqrt(static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
                                  static_cast<double>(s.vz[i]) * s.vz[i]));
  }
  return fastest;
}
} // namespace parafluid::sph::delta
