#pragma once
// Internal to the SPH solver: what a triangle-mesh boundary adds to the sums of a particle near it.
// The mesh is taken as flat within the kernel's reach (its tangent plane at the particle's nearest
// point) with the fluid's rest lattice continued beyond it as particles of the fluid's mass at rest,
// the "wall weight" idea of Kulasegaram et al. (2004) and Harada, Koshizuka & Shimazaki (2007).
// A particle at distance d from the mesh then has
//   sum_b W_ib = S(d)                  (density, in units of the fluid's particle mass),
//   sum_b grad_i W_ib = S'(d) n        (n the unit vector from the mesh to the particle; S' < 0),
// tabulated once per run for the solver's kernel. Without it a particle on the mesh has a cut
// neighbourhood, the layers above press it onto the mesh until the fluid alone sums to rest
// density, and a pond on a terrain stands about two spacings below the level its volume gives.
// The box walls have their exact mirror images (WallMirrors.h); the mesh has this. DFSPH adds it to
// its density, density rate and pressure impulse (the wall's k_b = 0, Bender & Koschier 2017);
// δ-SPH treats the lattice as the particle's mirror image (p_b = p_i, hence 2 m in its density),
// and moves density by the change of S with position rather than by a rate, which a bounce off the
// mesh would leave unbalanced.
#include "parafluid/sph/SPHParameters.h"

#include <cstdint>
#include <vector>

namespace parafluid::sph::detail
{
class MeshWallTable
{
public:
  MeshWallTable() = default;
  /// For the kernel `kernel` of support radius h and fluid particles on a lattice of `spacing`.
  MeshWallTable(DensityKernel kernel, float h, float spacing);

  struct Weight
  {
    float sum = 0.0f;        // S(d) [1/m^3]
    float slope = 0.0f;      // S'(d) [1/m^4]
    float neighbours = 0.0f; // lattice particles beyond the wall within h
  };
  /// The wall's sums at distance d [m] from it (zero at and beyond reach()).
  Weight at(float d) const;
  /// The distance from which the wall adds nothing [m]: h less half a spacing.
  float reach() const { return this->Reach; }
  bool empty() const { return this->Sum.empty(); }

private:
  float Reach = 0.0f, InverseStep = 0.0f;
  std::vector<float> Sum, Slope, Count; // at d = k / InverseStep
};

/// Each particle's nearest mesh point within the table's reach: distance (a value >= reach when
/// none) and the unit vector from the mesh to the particle.
struct MeshWallContacts
{
  std::vector<float> distance;
  std::vector<float> normal;           // x, y, z per particle
  std::vector<std::uint32_t> triangle; // the mesh triangle it was found on (a hint for the next search)
};

/// The table of a run and the contacts of the current positions (SPHSolver::findMeshWalls).
struct MeshWall
{
  MeshWallTable table;
  MeshWallContacts contacts;

  /// Particle i's wall sums and the wall's normal; false when no mesh is within reach.
  bool of(std::size_t i, MeshWallTable::Weight& weight, const float*& normal) const
  {
    const float d = this->contacts.distance[i];
    if (!(d < this->table.reach()))
    {
      return false;
    }
    weight = this->table.at(d);
    normal = &this->contacts.normal[3 * i];
    return true;
  }
};
} // namespace parafluid::sph::detail
