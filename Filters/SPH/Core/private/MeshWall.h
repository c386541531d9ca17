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
#include "parafluid/common/HostDevice.h"
#include "parafluid/common/TriangleMeshView.h"
#include "parafluid/sph/SPHParameters.h"

#include <cstdint>
#include <vector>

namespace parafluid::sph::detail
{
/// A wall's sums at distance d from it, linearly interpolated in a table (MeshWallTable's, or a
/// device copy of it); plain arrays, so the CPU and the GPU read it alike.
struct MeshWallTableView
{
  struct Weight
  {
    float sum = 0.0f;        // S(d) [1/m^3]
    float slope = 0.0f;      // S'(d) [1/m^4]
    float neighbours = 0.0f; // lattice particles beyond the wall within h
  };
  const float* sum = nullptr; // at d = k / inverseStep, k = 0 .. samples + 1
  const float* slope = nullptr;
  const float* count = nullptr;
  int samples = 0; // 0: no table (every distance gets a zero weight)
  float reach = 0.0f, inverseStep = 0.0f;

  PARAFLUID_HOST_DEVICE Weight at(float d) const
  {
    Weight out;
    if (this->samples == 0 || !(d < this->reach))
    {
      return out;
    }
    const float x = (d > 0.0f ? d : 0.0f) * this->inverseStep;
    const int k = static_cast<int>(x) < this->samples - 1 ? static_cast<int>(x) : this->samples - 1;
    const float f = x - static_cast<float>(k);
    out.sum = this->sum[k] + f * (this->sum[k + 1] - this->sum[k]);
    out.slope = this->slope[k] + f * (this->slope[k + 1] - this->slope[k]);
    out.neighbours = this->count[k] + f * (this->count[k + 1] - this->count[k]);
    return out;
  }
};

/// The wall of the mesh at p: its distance (reach when none within it) and the unit vector from
/// the mesh to p (zero when none); `triangle` holds a hint on entry and the triangle found on exit.
/// The fluid's side of a mesh is the one its faces' normals point to (a terrain's top, an
/// obstacle's outside): a particle behind it (on a container's mesh that faces out, or pushed
/// through) gets no wall, which would push it further in.
PARAFLUID_HOST_DEVICE inline void findMeshWall(const TriangleMeshView& mesh, const float p[3], float reach,
                                               float& distance, float normal[3], std::uint32_t& triangle)
{
  distance = reach;
  bool near = mesh.nearest(p, reach, distance, normal, &triangle, triangle);
  if (near)
  {
    const float* face = mesh.faceNormal(triangle);
    near = normal[0] * face[0] + normal[1] * face[1] + normal[2] * face[2] > 0.0f;
  }
  if (!near)
  {
    distance = reach;
    normal[0] = normal[1] = normal[2] = 0.0f;
  }
}

class MeshWallTable
{
public:
  MeshWallTable() = default;
  /// For the kernel `kernel` of support radius h and fluid particles on a lattice of `spacing`.
  MeshWallTable(DensityKernel kernel, float h, float spacing);

  using Weight = MeshWallTableView::Weight;
  /// The wall's sums at distance d [m] from it (zero at and beyond reach()).
  Weight at(float d) const { return this->view().at(d); }
  /// The table over its arrays (valid while it lives); the arrays, for a copy on the GPU.
  MeshWallTableView view() const;
  const std::vector<float>& sums() const { return this->Sum; }
  const std::vector<float>& slopes() const { return this->Slope; }
  const std::vector<float>& counts() const { return this->Count; }
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
