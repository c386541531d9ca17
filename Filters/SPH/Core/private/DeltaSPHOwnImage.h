#pragma once
// δ-SPH's wall images: the pair of a particle and its own image across one wall takes a profile
// that stiffens as the particle nears the wall, in continuity and momentum alike.
#include "private/DeltaSPHPairs.h"

namespace parafluid::sph::delta
{
/// A wall holds a particle off by the pair of the particle and its own image, 2 z apart at distance z
/// from the wall. Wendland C2's |dW/dr| peaks at a quarter of the support H, so at H = 3 spacings a
/// first layer (image one spacing away) sits just outside the peak: the push stiffens little as
/// the particle nears the wall, and goes soft inside 0.375 spacings, too soft to hold a floor layer
/// under a resting column (docs/design-notes.md). For that pair alone (in continuity and momentum alike, so the
/// pressure's work still matches the density's change) |dW/dr| takes the spiky kernel's profile (H − r)² down to
/// Wendland's peak (Desbrun & Gascuel 1996: a push that grows as particles close in), scaled to
/// equal Wendland's at one spacing, so a lattice at rest feels no difference; below the peak it
/// stays at its value there (Thomas & Couchman 1992), because a push growing to zero distance
/// throws back drops that arrive fast. Only for supports over 2.2 spacings
/// (see ownImageStiffened). Returns (dW/dr) / r.
PARAFLUID_HOST_DEVICE inline float ownImageGradient(const Constants& k, float r)
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

/// How much the pair of particle i (at x) and its own image (at q) changes its gradient, from the
/// kernel's to ownImageGradient; 0 where it does not. r is |q - x|.
PARAFLUID_HOST_DEVICE inline float ownImageChange(const float* q, const float* x, const Constants& k, float& r)
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
  // spacings) and would push corner particles into their corners.
  const int mirrored = static_cast<int>(q[0] != x[0]) + static_cast<int>(q[1] != x[1]) + static_cast<int>(q[2] != x[2]);
  if (mirrored != 1)
  {
    return 0.0f;
  }
  return ownImageGradient(k, r) - WendlandPair(k.w, r).gradient;
}

/// The same change of particle i's continuity sum.
PARAFLUID_HOST_DEVICE inline float ownImageDensityRate(const float* q, const float* vq, const float* x, const float* v,
                                                       const Constants& k)
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
} // namespace parafluid::sph::delta
