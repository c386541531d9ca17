#pragma once
// Internal to the SPH solver: a particle and its wall images as queries of a pair sum.
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

} // namespace parafluid::sph::detail
