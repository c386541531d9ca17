#pragma once
// Internal to the SPH solver: a particle and its wall images as queries of a pair sum.
#include "parafluid/common/HostDevice.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/WallMirrors.h"

namespace parafluid::sph::detail
{
/// Runs f(query position, query velocity, t, scale, isImage) for the particle and its wall images:
/// the term of x_i with the image R x_j equals R times the term of R x_i with x_j (R a
/// reflection); the image moves with the mirrored velocity, or for the laminar term of a no-slip
/// wall with the reversed one (t = S R, S the image's velocity scale).
template<class F>
void forEachWallImage(const float position[3], const float velocity[3], const SPHParameters& p, F&& f)
{
  static const float ones[3] = { 1.0f, 1.0f, 1.0f };
  f(position, velocity, ones, ones, false);
  const WallMirrors mirrors = WallMirrors::around(position, p, true);
  for (int m = 0; m < mirrors.count; ++m)
  {
    float image[3], imageVelocity[3], t[3];
    mirrors.image(m, position, image);
    for (int a = 0; a < 3; ++a)
    {
      imageVelocity[a] = mirrors.scale[m][a] * velocity[a];
      t[a] = mirrors.scale[m][a] * mirrors.velocityScale[m][a];
    }
    f(image, imageVelocity, t, mirrors.scale[m], true);
  }
}

/// The hydrostatic extrapolation of a wall image's pressure (Adami, Hu & Adams 2012, for a wall at
/// rest): the image R x_j of particle j carries p_j + rho_j g . (R x_j - x_j). With R x = s x + o
/// (s the mirror's scale, o = q - s x_i for the query q = R x_i), g . (R x_j - x_j) is linear in
/// x_j: lift[0..2] . x_j + lift[3].
PARAFLUID_HOST_DEVICE inline void hydrostaticImageLift(const float* q, const float* x, const float* scale,
                                                       const float* gravity, float lift[4])
{
  lift[3] = 0.0f;
  for (int a = 0; a < 3; ++a)
  {
    lift[a] = gravity[a] * (scale[a] - 1.0f);
    lift[3] += gravity[a] * (q[a] - scale[a] * x[a]);
  }
}

} // namespace parafluid::sph::detail
