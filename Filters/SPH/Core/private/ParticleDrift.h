#pragma once
// Internal to the SPH solver: one particle's drift through the box and past the boundary mesh, as
// every backend makes it (SPHSolver::drift on the CPU, the CUDA backend's drift kernel).
#include "parafluid/common/HostDevice.h"
#include "parafluid/common/TriangleMeshView.h"
#include "private/BoxWalls.h"

#include <algorithm>

namespace parafluid::sph::detail
{
/// What a drift moves a particle through: the box (SPHParameters::domainBounds, periodic,
/// wallRestitution) and the mesh (null when there is none; boundaryDamping).
struct DriftWalls
{
  float bounds[6];
  bool periodic[3];
  float restitution;
  const TriangleMeshView* mesh;
  float damping;
  float offset; // particles are put back this far off a mesh [m], so a step starts on a definite side
};

/// position += dt velocity within the walls; velocity reflected where a wall or the mesh is hit.
PARAFLUID_HOST_DEVICE inline void driftParticle(float position[3], float velocity[3], float dt, const DriftWalls& w)
{
  const float from[3] = { position[0], position[1], position[2] };
  float to[3];
  for (int a = 0; a < 3; ++a)
  {
    to[a] = from[a];
    moveAlongAxis(to[a], velocity[a], dt, w.bounds[2 * a], w.bounds[2 * a + 1], w.periodic[a], w.restitution);
  }
  // The box is convex and both ends of the move are inside it, so the mesh can only move the end
  // point back towards the start, except by the small offset, which the clamp takes care of.
  if (w.mesh && w.mesh->resolve(from, to, velocity, w.damping, w.offset))
  {
    float clamped[3];
    bool moved = false;
    for (int a = 0; a < 3; ++a)
    {
      clamped[a] = w.periodic[a] ? to[a] : std::clamp(to[a], w.bounds[2 * a], w.bounds[2 * a + 1]);
      moved = moved || clamped[a] != to[a];
    }
    // Clamping into the box can push a particle back across the mesh where the mesh leaves the
    // box (a sphere cut by a wall); then it stays where it was, which is on the right side.
    TriangleCrossing crossing;
    const bool back = moved && w.mesh->firstCrossing(from, clamped, crossing);
    for (int a = 0; a < 3; ++a)
    {
      to[a] = back ? from[a] : clamped[a];
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    position[a] = to[a];
  }
}
} // namespace parafluid::sph::detail
