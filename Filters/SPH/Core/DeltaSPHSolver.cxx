// δ-SPH: see DeltaSPHSolver.h for the scheme and its sources.
#include "parafluid/sph/DeltaSPHSolver.h"

#include "parafluid/common/Kernels.h"
#include "parafluid/common/SimdDispatch.h"
#include "parafluid/sph/WallMirrors.h"
#include "private/GradientCorrection.h"
#include "private/MeshWall.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"
#include "private/WallImages.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace parafluid::sph
{
using detail::addImageMoment;
using detail::applyGradientCorrection;
using detail::CandidateBuffer;
using detail::forEachParticleByCell;
using detail::forEachWallImage;
using detail::gradientCorrection;
using detail::threadCount;

namespace
{
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
  // (where both stiffen alike, and the stiffer profile's push near the wall blew up the violent
  // pillar-and-ramp run) keeps the plain kernel however the spacing computed from the mass rounds.
  bool ownImageStiffened;
  // The gradient correction (SPHParameters::gradientCorrection): its first moments are summed in
  // the continuity pass, and wall images carry hydrostatically extrapolated pressure.
  bool correctGradient;
  bool highPass; // SPHParameters::pushHighPass
};

struct Sums
{
  float a[3] = { 0, 0, 0 };
  float difference[3] = { 0, 0, 0 }; // sum_j m (p_j - p_i) / (rho_i rho_j) grad W_ij
  float densityRate = 0.0f;
  float smooth[4] = { 0, 0, 0, 0 }; // sum_j V_j W_ij, and sum_j V_j W_ij FullPush_j (x, y, z)
};

/// (dW/dr) / r of the Wendland kernel, and the kernel itself, at distance r. (Builtins only: it is
/// inlined into the pair loops' AVX-512 copies, which inline no ordinary function.)
struct WendlandPair
{
  float gradient, value;
  __attribute__((always_inline)) WendlandPair(const WendlandC2Kernel& w, float r)
  {
    const float q = r * w.inverseH;
    const float d = 1.0f - q > 0.0f ? 1.0f - q : 0.0f;
    const float d3 = d * d * d;
    gradient = -20.0f * w.coefficient * w.inverseH * w.inverseH * d3;
    value = w.coefficient * d3 * d * (1.0f + 4.0f * q);
  }
};

/// A wall holds a particle off by the pair of the particle and its own image, 2 z apart at distance z
/// from the wall. Wendland C2's |dW/dr| peaks at a quarter of the support H, so at H = 3 spacings a
/// first layer (image one spacing away) sits just outside the peak: the push stiffens little as
/// the particle nears the wall, and goes soft inside 0.375 spacings. Under a resting column a floor
/// particle then sank at constant density, its neighbours rising, and fell onto the floor after
/// about a second, setting still water moving (Testing/Benchmarks/README.md, "Still water: the
/// floor layer"). For that pair alone (in continuity and momentum alike, so the pressure's work
/// still matches the density's change) |dW/dr| takes the spiky kernel's profile (H − r)² down to
/// Wendland's peak (Desbrun & Gascuel 1996: a push that grows as particles close in), scaled to
/// equal Wendland's at one spacing, so a lattice at rest feels no difference; below the peak it
/// stays at its value there (Thomas & Couchman 1992), because a push growing to zero distance
/// blew up rain drops arriving at several m/s onto the floor. Only for supports over 2.2 spacings
/// (see ownImageStiffened). Returns (dW/dr) / r.
float ownImageGradient(const Constants& k, float r)
{
  if (!(r > 0.0f) || r >= k.w.h)
  {
    return 0.0f;
  }
  // Flat from the peak in, or from the rest distance where a wide kernel puts that inside the peak.
  const float flat = std::min(0.25f * k.w.h, k.ownImageRest);
  const float shape = (k.w.h - std::max(r, flat)) / (k.w.h - k.ownImageRest);
  return k.ownImageSlope * shape * shape / r;
}

/// The momentum factor F of a pair (a_i += m F grad W_ij): pressure, tensile correction and
/// artificial viscosity. x_ij = (dx, dy, dz), |x_ij|^2 = rr, value = W_ij; particle i's query
/// position and velocity q, vq, its density, 1 / density and p_i / rho_i^2 with its tensile part;
/// j's velocity, density and pressure. With Laminar, `laminar` gets the laminar term's factor L
/// (a_i += m L (dW/dr) / r w_ij, w_ij the pair's relative velocity: see laminarVelocity).
/// `inverseRhoJOut` gets 1 / rho_j, for the caller's difference sum.
template<bool Laminar>
__attribute__((always_inline)) inline float momentumFactor(float dx, float dy, float dz, float rr, float value,
                                                           const float* vq, float vxj, float vyj, float vzj, float rhoI,
                                                           float termI, float tensileI, float rhoJ, float pJ,
                                                           const Constants& k, float* laminar, float* inverseRhoJOut)
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
__attribute__((always_inline)) inline void laminarVelocity(const float* vq, float vxj, float vyj, float vzj,
                                                           const float* t, float& wx, float& wy, float& wz)
{
  wx = vq[0] - (NoSlipImage ? t[0] * vxj : vxj);
  wy = vq[1] - (NoSlipImage ? t[1] * vyj : vyj);
  wz = vq[2] - (NoSlipImage ? t[2] * vzj : vzj);
}

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

/// The momentum terms of particle i (position q, velocity vq, density and pressure) against the
/// candidates: pressure, tensile correction, artificial and laminar viscosity. `t` turns the
/// laminar term's relative velocity into that of a no-slip wall image (all ones and not read
/// without NoSlipImage); `lift` is read only with Lift (a wall image's query: the particle's own
/// neighbours have none, and skipping it saves four multiply-adds a pair).
template<bool Laminar, bool NoSlipImage, bool Lift>
__attribute__((always_inline)) inline void forceTermsBody(const PairInput& in, const float* q, const float* vq,
                                                          float rhoI, float pI, const float* t, const float* lift,
                                                          const Constants& k, Sums* out)
{
  const std::uint32_t count = in.count;
  const float *px = in.px, *py = in.py, *pz = in.pz;
  const float *vx = in.vx, *vy = in.vy, *vz = in.vz;
  const float *rho = in.rho, *pressure = in.pressure;
  const std::uint32_t* hits = in.hits;
  const float inverseRhoI = 1.0f / rhoI;
  const float termI = pI * inverseRhoI * inverseRhoI;
  const float tensileI = pI < 0.0f ? -kTensileCoefficient * termI : 0.0f;
  const float massOverRhoI = k.mass * inverseRhoI;
  const float *pushX = in.slowDeparture, *pushY = in.pushY, *pushZ = in.pushZ;
  float ax = 0.0f, ay = 0.0f, az = 0.0f, bx = 0.0f, by = 0.0f, bz = 0.0f;
  float sw = 0.0f, sx = 0.0f, sy = 0.0f, sz = 0.0f;
#pragma omp simd reduction(+ : ax, ay, az, bx, by, bz, sw, sx, sy, sz)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const float rr = dx * dx + dy * dy + dz * dz; // computed: a gather of the search's r^2 costs more
    const WendlandPair w(k.w, __builtin_sqrtf(rr));
    // A wall image's pressure, extrapolated hydrostatically from its particle's (lift: 0 for real
    // neighbours and without the gradient correction; see detail::hydrostaticImageLift).
    const float pJ =
      Lift ? pressure[j] + rho[j] * (lift[0] * px[j] + lift[1] * py[j] + lift[2] * pz[j] + lift[3]) : pressure[j];
    float laminar = 0.0f, inverseRhoJ;
    const float scalar = momentumFactor<Laminar>(dx, dy, dz, rr, w.value, vq, vx[j], vy[j], vz[j], rhoI, termI,
                                                 tensileI, rho[j], pJ, k, &laminar, &inverseRhoJ) *
                         (k.mass * w.gradient); // the product first, as before the factor was shared
    ax += scalar * dx;
    ay += scalar * dy;
    az += scalar * dz;
    const float difference = (pJ - pI) * (massOverRhoI * inverseRhoJ) * w.gradient;
    bx += difference * dx;
    by += difference * dy;
    bz += difference * dz;
    // The Shepard mean of the neighbours' FullPush for the push's high pass (pushHighPass).
    const float smoothing = k.mass * inverseRhoJ * w.value;
    sw += smoothing;
    sx += smoothing * pushX[j];
    sy += smoothing * pushY[j];
    sz += smoothing * pushZ[j];
    if constexpr (Laminar)
    {
      float wx, wy, wz;
      laminarVelocity<NoSlipImage>(vq, vx[j], vy[j], vz[j], t, wx, wy, wz);
      const float viscous = laminar * (k.mass * w.gradient);
      ax += viscous * wx;
      ay += viscous * wy;
      az += viscous * wz;
    }
  }
  out->a[0] = ax;
  out->a[1] = ay;
  out->a[2] = az;
  out->difference[0] = bx;
  out->difference[1] = by;
  out->difference[2] = bz;
  out->smooth[0] = sw;
  out->smooth[1] = sx;
  out->smooth[2] = sy;
  out->smooth[3] = sz;
}

// The pair loops compiled for AVX-512, AVX2 and the baseline, the widest this CPU runs picked
// at each call (parafluid/common/SimdDispatch.h).
PARAFLUID_SIMD_DISPATCH(laminarForceTerms,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, float pI, const float* t,
                         const float* lift, const Constants& k, Sums* out),
                        (in, q, vq, rhoI, pI, t, lift, k, out), (forceTermsBody<true, true, true>))
PARAFLUID_SIMD_DISPATCH(laminarInteriorForceTerms,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, float pI, const float* t,
                         const float* lift, const Constants& k, Sums* out),
                        (in, q, vq, rhoI, pI, t, lift, k, out), (forceTermsBody<true, false, false>))
PARAFLUID_SIMD_DISPATCH(inviscidForceTerms,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, float pI, const float* t,
                         const float* lift, const Constants& k, Sums* out),
                        (in, q, vq, rhoI, pI, t, lift, k, out), (forceTermsBody<false, false, true>))

template<bool Laminar>
Sums forceTerms(CandidateBuffer& c, const float q[3], const float vq[3], float rhoI, float pI, const float t[3],
                const float lift[4], bool image, const Constants& k)
{
  const PairInput in(c, q, k.h2, image);
  Sums sums;
  if constexpr (Laminar)
  {
    // The particle itself (t all ones) skips the no-slip image's velocity product.
    if (image)
      laminarForceTerms(in, q, vq, rhoI, pI, t, lift, k, &sums);
    else
      laminarInteriorForceTerms(in, q, vq, rhoI, pI, t, lift, k, &sums);
  }
  else
    inviscidForceTerms(in, q, vq, rhoI, pI, t, lift, k, &sums);
  return sums;
}

/// rho_i - rho^H(x_i), up to a constant: rho^H = rho0 (1 + g . x / c0^2), the linearised hydrostatic
/// density the diffusion leaves alone (densityRateBody).
float departureFromHydrostatic(const Constants& k, const ParticleState& s, std::size_t i)
{
  const float height = k.gravity[0] * s.x[i] + k.gravity[1] * s.y[i] + k.gravity[2] * s.z[i];
  return s.density[i] - k.rho0 - k.rho0 * height * k.inverseC0Squared;
}

/// D rho_i / D t: continuity, plus (when `diffuse`: real neighbours only, an image's density is the
/// particle's own, not that of the depth it is mirrored to) diffusion of the density's departure
/// from hydrostatic (Fourtakas et al. 2019, linearised: rho_j^H - rho_i^H = rho0 g . (x_j - x_i) /
/// c0^2 to first order in the compression, which stays about 1 % at c0 = 10 v_max). Between
/// particles whose neighbourhoods are full (fullness 1) the whole departure diffuses; as either
/// nears a free surface, only its fast part, the departure less its slow part (see
/// DeltaSPHSolver::SlowDeparture).
__attribute__((always_inline)) inline void densityRateBody(const PairInput& in, const float* q, const float* vq,
                                                           float rhoI, bool diffuse, float fullnessI, float slowI,
                                                           const Constants& k, float* out)
{
  const std::uint32_t count = in.count;
  const float *px = in.px, *py = in.py, *pz = in.pz;
  const float *vx = in.vx, *vy = in.vy, *vz = in.vz;
  const float* rho = in.rho;
  const float *fullness = in.fullness, *slow = in.slowDeparture;
  const std::uint32_t* hits = in.hits;
  const float diffusion = diffuse ? k.delta * k.hSmooth * k.c0 * 2.0f * k.mass : 0.0f;
  float rate = 0.0f, mxx = 0.0f, mxy = 0.0f, mxz = 0.0f, myy = 0.0f, myz = 0.0f, mzz = 0.0f;
  float gx = 0.0f, gy = 0.0f, gz = 0.0f, least = 1.0f;
#pragma omp simd reduction(+ : rate, mxx, mxy, mxz, myy, myz, mzz, gx, gy, gz) reduction(min : least)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const float rr = dx * dx + dy * dy + dz * dz;
    const WendlandPair w(k.w, __builtin_sqrtf(rr));
    const float approach = (vq[0] - vx[j]) * dx + (vq[1] - vy[j]) * dy + (vq[2] - vz[j]) * dz;
    const float hydrostatic =
      -k.rho0 * (k.gravity[0] * dx + k.gravity[1] * dy + k.gravity[2] * dz) * k.inverseC0Squared;
    const float psi = (rho[j] - rhoI) - hydrostatic - (1.0f - fullnessI * fullness[j]) * (slow[j] - slowI);
    // One division, and the quotient taken whole (finite for the padding's far sentinel).
    rate += w.gradient * (k.mass * approach - diffusion * psi * (rr / (rho[j] * (rr + k.eta2))));
    // The first moment sum_j V_j (x_j - x_i) (x) grad W_ij = -sum_j V_j x_ij x_ij^T (dW/dr) / r.
    const float v = -k.mass * w.gradient / rho[j];
    mxx += v * dx * dx;
    mxy += v * dx * dy;
    mxz += v * dx * dz;
    myy += v * dy * dy;
    myz += v * dy * dz;
    mzz += v * dz * dz;
    // G = sum_j m grad W_ij, the 2 p_i term's sum (pushHighPass).
    const float g = k.mass * w.gradient;
    gx += g * dx;
    gy += g * dy;
    gz += g * dz;
    least = fullness[j] < least ? fullness[j] : least; // the padding's sentinel has fullness 1
  }
  out[0] = rate;
  out[1] = mxx;
  out[2] = mxy;
  out[3] = mxz;
  out[4] = myy;
  out[5] = myz;
  out[6] = mzz;
  out[7] = gx;
  out[8] = gy;
  out[9] = gz;
  out[10] = least;
}

PARAFLUID_SIMD_DISPATCH(densityRateInto,
                        (const PairInput& in, const float* q, const float* vq, float rhoI, bool diffuse,
                         float fullnessI, float slowI, const Constants& k, float* out),
                        (in, q, vq, rhoI, diffuse, fullnessI, slowI, k, out), densityRateBody)

/// D rho_i / D t of one query (the particle or a wall image), and into moment the query's first
/// moment (xx, xy, xz, yy, yz, zz), its G = sum_j m grad W_ij (x, y, z) and the smallest fullness
/// (a step old) among its neighbours. fullnessI and slowI: the particle's (densityRateBody).
float densityRate(CandidateBuffer& c, const float q[3], const float vq[3], float rhoI, bool image, float fullnessI,
                  float slowI, const Constants& k, float moment[10])
{
  const PairInput in(c, q, k.h2, image);
  const bool diffuse = !image;
  float sums[11];
  densityRateInto(in, q, vq, rhoI, diffuse, fullnessI, slowI, k, sums);
  for (int m = 0; m < 10; ++m)
  {
    moment[m] = sums[1 + m];
  }
  return sums[0];
}

/// The sums of particle shifting at q over the padded hits: sum_j W_ij into out[0] and the
/// concentration gradient sum_j (dW/dr)/r (1 + 0.2 (W_ij / W(dp))^4) (q - x_j) into out[1..3].
/// (The padding's far sentinel adds exactly zero: its kernel value and gradient vanish.)
__attribute__((always_inline)) inline void shiftingSumsBody(const float* px, const float* py, const float* pz,
                                                            const std::uint32_t* hits, std::uint32_t count,
                                                            const float* q, const WendlandC2Kernel& w,
                                                            float inverseWSpacing, float* out)
{
  float ws = 0.0f, gx = 0.0f, gy = 0.0f, gz = 0.0f;
#pragma omp simd reduction(+ : ws, gx, gy, gz)
  for (std::uint32_t n = 0; n < count; ++n)
  {
    const int j = static_cast<int>(hits[n]); // signed: a gather sign-extends its 32-bit indices
    const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
    const WendlandPair pair(w, __builtin_sqrtf(dx * dx + dy * dy + dz * dz));
    const float f = pair.value * inverseWSpacing;
    const float f2 = f * f;
    const float weight = pair.gradient * (1.0f + 0.2f * f2 * f2);
    ws += pair.value;
    gx += weight * dx;
    gy += weight * dy;
    gz += weight * dz;
  }
  out[0] = ws;
  out[1] = gx;
  out[2] = gy;
  out[3] = gz;
}

PARAFLUID_SIMD_DISPATCH(shiftingSums,
                        (const float* px, const float* py, const float* pz, const std::uint32_t* hits,
                         std::uint32_t count, const float* q, const WendlandC2Kernel& w, float inverseWSpacing,
                         float* out),
                        (px, py, pz, hits, count, q, w, inverseWSpacing, out), shiftingSumsBody)

/// How much the pair of particle i (at x) and its own image (at q) changes its gradient, from the
/// kernel's to ownImageGradient; 0 where it does not. r is |q - x|.
float ownImageChange(const float* q, const float* x, const Constants& k, float& r)
{
  if (!k.ownImageStiffened)
  {
    return 0.0f;
  }
  r = std::sqrt((q[0] - x[0]) * (q[0] - x[0]) + (q[1] - x[1]) * (q[1] - x[1]) + (q[2] - x[2]) * (q[2] - x[2]));
  if (!(r > 0.0f) || r >= k.w.h)
  {
    return 0.0f;
  }
  // Only an image across one wall: the profile is scaled to Wendland's gradient at one spacing, and
  // an image across two or three walls (a particle in an edge or corner) rests sqrt(2) or sqrt(3)
  // spacings away, where that profile pushes less than Wendland's (by 11 % at sqrt(2) and H = 3
  // spacings): it pushed corner particles into their corners, the largest speeds of a resting
  // tank's first second (Testing/Benchmarks/README.md, "Still water, met").
  const int mirrored = static_cast<int>(q[0] != x[0]) + static_cast<int>(q[1] != x[1]) + static_cast<int>(q[2] != x[2]);
  if (mirrored != 1)
  {
    return 0.0f;
  }
  return ownImageGradient(k, r) - WendlandPair(k.w, r).gradient;
}

/// Adds to `a` (before the image's mapping back) the change of the momentum sum of particle i (at x
/// with velocity v, density rho, pressure p) against its own image (at q with velocity vq) when
/// that pair takes ownImageGradient.
template<bool Laminar>
void addOwnImageForce(const float* q, const float* vq, const float* t, const float* x, const float* v, float rho,
                      float p, const Constants& k, float* a)
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

/// The same change of particle i's continuity sum.
float ownImageDensityRate(const float* q, const float* vq, const float* x, const float* v, const Constants& k)
{
  float r = 0.0f;
  const float change = ownImageChange(q, x, k, r);
  if (change == 0.0f)
  {
    return 0.0f;
  }
  const float approach =
    (vq[0] - v[0]) * (q[0] - x[0]) + (vq[1] - v[1]) * (q[1] - x[1]) + (vq[2] - v[2]) * (q[2] - x[2]);
  return k.mass * approach * change;
}

template<bool Laminar>
void forcePass(const NeighbourGrid& grid, ParticleState& s, const SPHParameters& p, const Constants& k,
               const detail::MeshWall* wall, const float* correction, const float* push, const float* interior)
{
  const std::size_t n = s.size();
  forEachParticleByCell(
    grid, s, p.smoothingLength, threadCount(p),
    { s.vx.data(), s.vy.data(), s.vz.data(), s.density.data(), s.pressure.data(), push, push + n, push + 2 * n },
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
      float a[3] = { p.gravity[0], p.gravity[1], p.gravity[2] };
      float difference[3] = { 0.0f, 0.0f, 0.0f };
      float smooth[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
      forEachWallImage(position, velocity, p,
                       [&](const float* q, const float* v, const float* t, const float* scale, bool image)
                       {
                         float lift[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
                         if (image && k.correctGradient)
                         {
                           // Without the lift the image of every neighbour has that neighbour's
                           // pressure, so the pressure field is even across a floor and a floor
                           // layer's neighbours and their images push it equally up and down: at
                           // rest it was held up by its own image's pair alone.
                           detail::hydrostaticImageLift(q, position, scale, k.gravity, lift);
                         }
                         Sums g = forceTerms<Laminar>(c, q, v, s.density[i], s.pressure[i], t, lift, image, k);
                         if (image)
                         {
                           addOwnImageForce<Laminar>(q, v, t, position, velocity, s.density[i], s.pressure[i], k, g.a);
                         }
                         for (int d = 0; d < 3; ++d)
                         {
                           a[d] += scale[d] * g.a[d];
                           difference[d] += scale[d] * g.difference[d];
                           smooth[1 + d] += scale[d] * g.smooth[1 + d];
                         }
                         smooth[0] += g.smooth[0];
                       });
      if (k.highPass && smooth[0] > 0.0f)
      {
        // The symmetric form's -2 C p_i / rho_i^2 G_i less its smooth part: + 2 C p_i / rho_i^2
        // times the Shepard mean of the neighbours' Interior-weighted G, where i is inside the
        // fluid (SPHParameters::pushHighPass). The mean is over the wall images too, mirrored, so
        // a wall's own-image push (odd across the wall) survives it.
        const float rho = s.density[i];
        const float factor = 2.0f * k.pressureCorrection * s.pressure[i] / (rho * rho) * interior[i] / smooth[0];
        for (int d = 0; d < 3; ++d)
        {
          a[d] += factor * smooth[1 + d];
        }
      }
      if (correction)
      {
        // The momentum sum holds -C sum_j m (p_j - p_i) / (rho_i rho_j) grad W_ij among its terms;
        // corrected, that part is -L times the sum (gradientCorrection: L - C I).
        applyGradientCorrection(correction + 6 * static_cast<std::size_t>(i), difference, a);
      }
      detail::MeshWallTable::Weight weight;
      const float* normal = nullptr;
      if (wall && wall->of(i, weight, normal))
      {
        // The mesh's lattice is the particle's mirror image: p_b = p_i, negative
        // too (a wall that only pushed would take in energy wherever the water
        // is in tension, as a film spreading over a terrain is).
        const float rho = s.density[i];
        const float term = s.pressure[i] / (rho * rho);
        const float scalar = -2.0f * k.pressureCorrection * term * k.mass * weight.slope;
        for (int d = 0; d < 3; ++d)
        {
          a[d] += scalar * normal[d];
        }
      }
      s.ax[i] = a[0];
      s.ay[i] = a[1];
      s.az[i] = a[2];
    });
}

double gravityMagnitude(const SPHParameters& p)
{
  return std::sqrt(static_cast<double>(p.gravity[0]) * p.gravity[0] + static_cast<double>(p.gravity[1]) * p.gravity[1] +
                   static_cast<double>(p.gravity[2]) * p.gravity[2]);
}

/// The fluid's height along gravity [m], counting its top layer of particles (half a kernel radius).
double fluidHeight(const SPHParameters& p, const ParticleState& s)
{
  const double g = gravityMagnitude(p);
  double lowest = 0.0, highest = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const double along = g > 0.0 ? -(s.x[i] * p.gravity[0] + s.y[i] * p.gravity[1] + s.z[i] * p.gravity[2]) / g : 0.0;
    lowest = i == 0 ? along : std::min(lowest, along);
    highest = i == 0 ? along : std::max(highest, along);
  }
  return highest - lowest + 0.5 * p.smoothingLength;
}
} // namespace

double DeltaSPHSolver::automaticSoundSpeed(const SPHParameters& p, const ParticleState& s)
{
  if (p.soundSpeed > 0.0f)
  {
    return p.soundSpeed;
  }
  const double g = gravityMagnitude(p);
  double fastest = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    fastest =
      std::max(fastest, std::sqrt(static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
                                  static_cast<double>(s.vz[i]) * s.vz[i]));
  }
  const double height = fluidHeight(p, s);
  double speed = std::max(std::sqrt(2.0 * g * height), fastest);
  if (p.surfaceTension > 0.0f)
  {
    // Cohesion holds the fluid under a pressure of about 10 sigma / h (Akinci's force at water's
    // 0.0728 N/m and h = 1 mm: 800 Pa); the sound speed keeps that pressure's compression at ~1 %.
    speed = std::max(speed, std::sqrt(10.0 * p.surfaceTension / (p.restDensity * p.smoothingLength)));
  }
  return 10.0 * std::max(speed, 0.1); // at least 1 m/s, for a scene at rest without gravity
}

SolverEntry DeltaSPHSolver::registryEntry()
{
  SolverEntry e{};
  e.type = PressureSolverType::DeltaSPH;
  e.key = "DeltaSPH";
  e.label = "δ-SPH";
  e.propertyValue = 2;
  e.kernel = DensityKernel::WendlandC2;
  e.defaultSupport = kDeltaSPHSupport;
  e.minimumSupport = kDeltaSPHSupport; // an input's narrower smoothing_length runs its waves fast
  e.viscousOperator = ViscousOperator::Morris;
  e.explicitLaminarViscosity = true;
  e.meshWallInSums = true;
  // Under the cloudburst of Runoff.BasinKeepsTheRainVolume, with the terrain in its sums it ran or
  // blew up by rounding; without it, it ran on every machine tried.
  e.meshWallInRunoff = false;
  e.particleShifting = true;
  e.holdsStrongCohesion = true;
  e.runoffCFLNumber = 0.1f; // at 0.2 its integrated density drifted up under a cloudburst
  e.create = [] { return std::unique_ptr<PressureSolver>(std::make_unique<DeltaSPHSolver>()); };
  e.stabilityAdvice = [](bool adaptive) -> std::string
  {
    return adaptive ? "lower CFLNumber or MaxTimeStep, or raise SoundSpeed (a stiffer, less compressible "
                      "fluid) or ArtificialViscosity"
                    : "lower TimeStep or turn on AdaptiveTimeStep (the step must stay below the CFL limit of "
                      "the speed of sound SoundSpeed)";
  };
  return e;
}

void DeltaSPHSolver::start(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  this->SoundSpeed = automaticSoundSpeed(sim.parameters(), s);
  // The slow part of the density's departure follows it over the fluid's free-fall time over its
  // own height: ten sqrt(2) times the time sound crosses that height at the automatic c0, and 3.5
  // times the slowest acoustic period (4 H / c0), so acoustic noise stays in the fast part; a
  // departure held longer than that (a truncated kernel's at a free surface at rest) counts as slow.
  // Without gravity nothing holds the surface off hydrostatic, and the whole departure diffuses.
  const double g = gravityMagnitude(sim.parameters());
  this->SlowDepartureTime = g > 0.0 ? std::sqrt(fluidHeight(sim.parameters(), s) / g) : 0.0;
  this->PressureCorrection =
    latticeGradientCorrection(sim.particleSpacing(), sim.parameters().smoothingLength, DensityKernel::WendlandC2);
  // Density is state here: a given one (a prepared initial condition) is kept; otherwise the
  // fluid starts in hydrostatic equilibrium, so a resting column does not ring acoustically.
  const bool given = !s.density.empty() && std::all_of(s.density.begin(), s.density.end(),
                                                       [](float rho) { return std::isfinite(rho) && rho > 0.0f; });
  if (!given)
  {
    this->startHydrostatic(sim);
  }
  this->DensityRate.assign(s.size(), 0.0f);
  this->startSlowDeparture(sim);
  // The wall's sum where each particle starts: its density counts from there.
  this->WallSum.assign(s.size(), 0.0f);
  if (sim.wall())
  {
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      this->WallSum[i] = sim.wall()->table.at(sim.wall()->contacts.distance[i]).sum;
    }
  }
  this->updatePressure(sim);
  this->computeAccelerations(sim);
}

void DeltaSPHSolver::startHydrostatic(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  std::fill(s.density.begin(), s.density.end(), p.restDensity);
  // Gravity along one axis only (the usual case); otherwise rest density, which settles acoustically.
  int down = -1;
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    if (p.gravity[a] != 0.0f && p.gravity[b] == 0.0f && p.gravity[c] == 0.0f)
    {
      down = a;
    }
  }
  if (down < 0 || s.size() == 0 || p.periodic[down])
  {
    return; // no gravity, gravity off an axis, or along a periodic axis (a body force without a top)
  }
  // Depth of each particle below the top of its column (columns one spacing wide across gravity),
  // plus half a spacing: the free surface lies half a spacing above the top particle.
  const int b = (down + 1) % 3, c = (down + 2) % 3;
  const float* position[3] = { s.x.data(), s.y.data(), s.z.data() };
  const float sign = p.gravity[down] < 0.0f ? 1.0f : -1.0f; // height grows against gravity
  const float d = sim.particleSpacing();
  std::unordered_map<std::int64_t, float> top;
  auto key = [&](std::size_t i)
  {
    const auto u = static_cast<std::int64_t>(std::floor(position[b][i] / d));
    const auto v = static_cast<std::int64_t>(std::floor(position[c][i] / d));
    return u * 2000003LL + v;
  };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const float height = sign * position[down][i];
    auto [it, inserted] = top.emplace(key(i), height);
    if (!inserted)
    {
      it->second = std::max(it->second, height);
    }
  }
  const double g = std::fabs(p.gravity[down]);
  const double bulk = this->SoundSpeed * this->SoundSpeed * p.restDensity / kGamma;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const double depth = top[key(i)] - sign * position[down][i] + 0.5 * d;
    s.density[i] = static_cast<float>(p.restDensity * std::pow(1.0 + p.restDensity * g * depth / bulk, 1.0 / kGamma));
  }
}

void DeltaSPHSolver::permute(SimulationParts& sim, const std::vector<std::uint32_t>& order, std::vector<float>& scratch,
                             int threads)
{
  // Density is state here (it is integrated, not summed), so it moves with its particle.
  ParticleState& s = sim.state();
  for (auto* a : { &s.density, &this->DensityRate, &this->WallSum, &this->Fullness, &this->SlowDeparture })
  {
    if (a->size() == s.size())
    {
      detail::permute(*a, scratch, order, threads);
    }
  }
  this->CorrectionFresh = false; // summed again where the particles now are
}

void DeltaSPHSolver::updatePressure(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const float rho0 = sim.parameters().restDensity;
  const auto b = static_cast<float>(this->SoundSpeed * this->SoundSpeed * rho0 / kGamma);
  const float inverseRho0 = 1.0f / rho0;
  const auto n = static_cast<std::int64_t>(s.size());
#pragma omp parallel for simd schedule(static) num_threads(threadCount(sim.parameters()))
  for (std::int64_t i = 0; i < n; ++i)
  {
    const float ratio = s.density[i] * inverseRho0;
    const float r2 = ratio * ratio;
    s.pressure[i] = b * (r2 * r2 * r2 * ratio - 1.0f);
  }
}

namespace
{
Constants constants(const SPHParameters& p, double soundSpeed, float spacing, float laplacianCorrection,
                    float pressureCorrection)
{
  const WendlandC2Kernel w(p.smoothingLength);
  const float restSpacing = std::min(spacing, 0.99f * p.smoothingLength); // inside the support
  return Constants{ w.h2,
                    0.5f * p.smoothingLength,
                    0.01f * 0.25f * w.h2,
                    p.particleMass,
                    static_cast<float>(soundSpeed),
                    p.artificialViscosity,
                    p.densityDiffusion,
                    // Müller's extra viscosity, when set, joins the physical one here.
                    2.0f * (p.kinematicViscosity + p.viscosity / p.restDensity) * laplacianCorrection,
                    p.restDensity,
                    static_cast<float>(1.0 / (soundSpeed * soundSpeed)),
                    // Gravity along a periodic axis drives a flow and builds no hydrostatic pressure.
                    { p.periodic[0] ? 0.0f : p.gravity[0], p.periodic[1] ? 0.0f : p.gravity[1],
                      p.periodic[2] ? 0.0f : p.gravity[2] },
                    1.0f / w.value(restSpacing),
                    w,
                    pressureCorrection,
                    w.radialDerivative(restSpacing),
                    restSpacing,
                    spacing < 0.45f * p.smoothingLength,
                    p.gradientCorrection,
                    p.pushHighPass };
}
} // namespace

void DeltaSPHSolver::computeAccelerations(SimulationParts& sim)
{
  const Constants k = constants(sim.parameters(), this->SoundSpeed, sim.particleSpacing(), sim.laplacianCorrection(),
                                this->PressureCorrection);
  if (!this->CorrectionFresh)
  {
    // At the start (the step sums these with the density rates). FullPush is summed and gathered
    // even with pushHighPass off: the force pass's loop reads it either way.
    this->sumDensityRates(sim);
  }
  const float* correction = k.correctGradient ? this->Correction.data() : nullptr;
  if (sim.parameters().kinematicViscosity > 0.0f || sim.parameters().viscosity > 0.0f)
  {
    forcePass<true>(sim.grid(), sim.state(), sim.parameters(), k, sim.wall(), correction, this->FullPush.data(),
                    this->Interior.data());
  }
  else
  {
    forcePass<false>(sim.grid(), sim.state(), sim.parameters(), k, sim.wall(), correction, this->FullPush.data(),
                     this->Interior.data());
  }
  this->CorrectionFresh = false;
  sim.addSurfaceTension();
}

void DeltaSPHSolver::sumDensityRates(SimulationParts& sim)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const Constants k = constants(sim.parameters(), this->SoundSpeed, sim.particleSpacing(), sim.laplacianCorrection(),
                                this->PressureCorrection);
  this->DensityRate.resize(s.size());
  this->Correction.resize(k.correctGradient ? 6 * s.size() : 0);
  this->NextFullness.resize(s.size());
  this->FullPush.resize(3 * s.size());
  this->Interior.resize(s.size());
  forEachParticleByCell(
    sim.grid(), s, p.smoothingLength, threadCount(p),
    { s.vx.data(), s.vy.data(), s.vz.data(), s.density.data(), this->Fullness.data(), this->SlowDeparture.data() },
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      const float velocity[3] = { s.vx[i], s.vy[i], s.vz[i] };
      float rate = 0.0f, moment[6] = { 0, 0, 0, 0, 0, 0 }, push[3] = { 0, 0, 0 }, least = 1.0f;
      forEachWallImage(position, velocity, p,
                       [&](const float* q, const float* v, const float*, const float* scale, bool image)
                       {
                         float queryMoment[10];
                         rate += densityRate(c, q, v, s.density[i], image, this->Fullness[i], this->SlowDeparture[i], k,
                                             queryMoment);
                         addImageMoment(queryMoment, scale, moment);
                         for (int d = 0; d < 3; ++d)
                         {
                           push[d] += scale[d] * queryMoment[6 + d];
                         }
                         least = std::min(least, queryMoment[9]);
                         if (image)
                         {
                           rate += ownImageDensityRate(q, v, position, velocity, k);
                         }
                       });
      this->DensityRate[i] = rate;
      if (k.correctGradient)
      {
        gradientCorrection(moment, k.pressureCorrection, &this->Correction[6 * i]);
      }
      this->NextFullness[i] = detail::neighbourhoodFullness(moment, k.pressureCorrection);
      // Full, and so are its neighbours (a step ago, as the diffusion reads them; at the start every
      // particle counts as full until this first pass): no surface within a kernel of any of them.
      // (A particle two spacings under a surface has a full first moment but a cut kernel, whose
      // G is the surface's push; smoothing that in pulled a drop's surface layers inwards.)
      this->Interior[i] = this->NextFullness[i] * least;
      for (int d = 0; d < 3; ++d)
      {
        this->FullPush[d * s.size() + i] = this->Interior[i] * push[d];
      }
    });
  // Written after the pass, which reads every neighbour's: the next step's diffusion uses these.
  std::swap(this->Fullness, this->NextFullness);
  this->CorrectionFresh = true;
}

void DeltaSPHSolver::advanceDensity(SimulationParts& sim, float dt)
{
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  this->sumDensityRates(sim);
  // Written after the pass: the pass reads every neighbour's density of this step.
  const auto n = static_cast<std::int64_t>(s.size());
  float* rho = s.density.data();
  const float* rate = this->DensityRate.data();
#pragma omp parallel for simd schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < n; ++i)
  {
    rho[i] += dt * rate[i];
  }
  if (sim.wall())
  {
    // The mesh's wall moves density with the particle's position, not its velocity: the change of
    // the wall's sum since the last step. Its lattice is the particle's mirror image (moving with
    // the mirrored velocity, p_b = p_i), hence 2 m. Position, not rate: a particle the mesh bounces
    // back gets its compression back, which a rate integrated over the bounce does not give.
    const float twiceMass = 2.0f * p.particleMass;
    const detail::MeshWall& wall = *sim.wall();
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
    for (std::int64_t i = 0; i < n; ++i)
    {
      const float sum = wall.table.at(wall.contacts.distance[i]).sum;
      rho[i] += twiceMass * (sum - this->WallSum[i]);
      this->WallSum[i] = sum;
    }
  }
  this->followSlowDeparture(sim, dt);
}

void DeltaSPHSolver::resize(std::size_t n)
{
  // Added particles (SPHSolver::addParticles): full neighbourhoods until the next continuity pass
  // says otherwise, and a slow departure that start() takes from where they are.
  this->Fullness.resize(n, 1.0f);
  this->SlowDeparture.resize(n, std::numeric_limits<float>::quiet_NaN());
}

void DeltaSPHSolver::startSlowDeparture(SimulationParts& sim)
{
  // Kept across a restart (particles added: see resize); otherwise each particle's slow departure
  // starts at its departure, so the fluid as given counts as settled.
  const ParticleState& s = sim.state();
  const std::size_t n = s.size();
  if (this->Fullness.size() != n || this->SlowDeparture.size() != n)
  {
    this->Fullness.assign(n, 1.0f);
    this->SlowDeparture.assign(n, std::numeric_limits<float>::quiet_NaN());
  }
  const Constants k = constants(sim.parameters(), this->SoundSpeed, sim.particleSpacing(), sim.laplacianCorrection(),
                                this->PressureCorrection);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!std::isfinite(this->SlowDeparture[i]) || !(this->SlowDepartureTime > 0.0))
    {
      this->SlowDeparture[i] = this->SlowDepartureTime > 0.0 ? departureFromHydrostatic(k, s, i) : 0.0f;
    }
  }
}

void DeltaSPHSolver::followSlowDeparture(SimulationParts& sim, float dt)
{
  const SPHParameters& p = sim.parameters();
  if (!(p.densityDiffusion > 0.0f) || !(this->SlowDepartureTime > 0.0))
  {
    return; // nothing diffuses, or (no gravity) the slow part stays 0
  }
  const Constants k =
    constants(p, this->SoundSpeed, sim.particleSpacing(), sim.laplacianCorrection(), this->PressureCorrection);
  const float follow = static_cast<float>(std::min(1.0, dt / this->SlowDepartureTime));
  const ParticleState& s = sim.state();
  const auto n = static_cast<std::int64_t>(s.size());
  float* slow = this->SlowDeparture.data();
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < n; ++i)
  {
    slow[i] += follow * (departureFromHydrostatic(k, s, static_cast<std::size_t>(i)) - slow[i]);
  }
}

void DeltaSPHSolver::shiftParticles(SimulationParts& sim, float dt)
{
  // Particle shifting (Lind et al. 2012) with the coefficient of the δ+-SPH scheme (Sun, Colagrossi,
  // Marrone & Zhang 2017): each interior particle moves down the gradient of particle concentration,
  //   dr_i = -CFL Ma (2 h_s)^2 grad C_i, grad C_i = sum_j V_j (1 + 0.2 (W_ij / W(dp))^4) grad W_ij,
  // with h_s the smoothing length (half the support H), Ma = U_max / c0 and CFL = c0 dt / h_s, so
  // CFL Ma (2 h_s)^2 = 2 H U_max dt: the shift per unit time depends on neither c0 nor the step.
  // It keeps the distribution uniform where the flow stretches it (the vortices of a Taylor-Green
  // flow, a splash's rarefaction) without a force. (Skillen et al. 2013's D = 0.5 H |v_i| dt, used
  // before, is 4 x weaker where particles move at U_max and vanishes at the stagnation points where
  // the vortex lines particles up: the Taylor-Green vortex broke down into particle noise at
  // t U / L = 0.15 and lost 61 % more energy than the analytic decay at 25 particles across.)
  // Free-surface particles (kernel sum below 0.9, their neighbourhood cut) are not shifted: their
  // concentration gradient points out of the fluid. Fluid at rest (U_max = 0) is not shifted.
  ParticleState& s = sim.state();
  const SPHParameters& p = sim.parameters();
  const std::size_t n = s.size();
  this->Shift.assign(3 * n, 0.0f);
  const WendlandC2Kernel w(p.smoothingLength);
  const float volume = p.particleMass / p.restDensity;
  const float inverseWSpacing = 1.0f / w.value(std::min(sim.particleSpacing(), 0.99f * p.smoothingLength));
  const float limit = 0.2f * sim.particleSpacing();
  const auto count = static_cast<std::int64_t>(n);
  const auto fastest = static_cast<float>(sim.largestLength(s.vx, s.vy, s.vz));
  if (fastest == 0.0f)
  {
    return;
  }
  const float diffusion = 2.0f * p.smoothingLength * fastest * dt * volume;
  forEachParticleByCell(
    sim.grid(), s, p.smoothingLength, threadCount(p), {},
    [&](CandidateBuffer& c, std::uint32_t i)
    {
      const float position[3] = { s.x[i], s.y[i], s.z[i] };
      float sum = 0.0f, g[3] = { 0.0f, 0.0f, 0.0f };
      forEachWallImage(position, position, p,
                       [&](const float* q, const float*, const float*, const float* scale, bool image)
                       {
                         // The pair loops' hits (an image's among its particle's own); no channel is read.
                         const PairInput in(c, q, w.h2, image);
                         float sums[4];
                         shiftingSums(in.px, in.py, in.pz, in.hits, in.count, q, w, inverseWSpacing, sums);
                         sum += sums[0];
                         g[0] += scale[0] * sums[1];
                         g[1] += scale[1] * sums[2];
                         g[2] += scale[2] * sums[3];
                       });
      if (volume * sum < 0.9f)
      {
        return;
      }
      float shift[3] = { -diffusion * g[0], -diffusion * g[1], -diffusion * g[2] };
      const float length = std::sqrt(shift[0] * shift[0] + shift[1] * shift[1] + shift[2] * shift[2]);
      const float scale = length > limit ? limit / length : 1.0f;
      for (int a = 0; a < 3; ++a)
      {
        this->Shift[3 * i + a] = scale * shift[a];
      }
    });
  // Applied after the pass (it reads every neighbour's position), through the walls' rules.
  const auto& b = p.domainBounds;
#pragma omp parallel for schedule(static) num_threads(threadCount(p))
  for (std::int64_t i = 0; i < count; ++i)
  {
    float* position[3] = { &s.x[i], &s.y[i], &s.z[i] };
    for (int a = 0; a < 3; ++a)
    {
      float x = *position[a] + this->Shift[3 * i + a];
      if (p.periodic[a])
      {
        const float length = b[2 * a + 1] - b[2 * a];
        x = x < b[2 * a] ? x + length : (x >= b[2 * a + 1] ? x - length : x);
      }
      else
      {
        x = std::clamp(x, b[2 * a] + 0.01f * sim.particleSpacing(), b[2 * a + 1] - 0.01f * sim.particleSpacing());
      }
      *position[a] = x;
    }
  }
}

double DeltaSPHSolver::step(SimulationParts& sim, double remaining)
{
  // Störmer-Verlet with density as a position-like variable: velocity at the half step moves the
  // particles and then changes the density, and the new density gives the forces of the second
  // half-kick. Density and velocity are never updated from each other's old values at once (that
  // forward-Euler coupling of the acoustic oscillation grows without bound).
  const double dt = sim.chooseTimeStep(remaining);
  const auto h = static_cast<float>(dt);
  sim.kick(0.5f * h);
  sim.drift(h);
  sim.sortByCell();
  if (sim.parameters().particleShifting)
  {
    this->shiftParticles(sim, h);
    // The shift moved particles by up to 0.2 spacings, some out of their grid cells: sorted again,
    // the passes after it find every pair within the support (about 2 % of a step).
    sim.sortByCell();
    sim.findMeshWalls();
  }
  this->advanceDensity(sim, h);
  this->updatePressure(sim);
  this->computeAccelerations(sim);
  sim.kick(0.5f * h);
  sim.applyWallFriction(h);
  sim.statistics().timeStep = dt;
  sim.advanceTime(dt);
  return dt;
}
} // namespace parafluid::sph
