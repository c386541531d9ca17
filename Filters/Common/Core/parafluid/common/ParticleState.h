#pragma once
// Structure-of-arrays particle state of the SPH solver (float: 64 bytes a particle).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid
{
struct ParticleState
{
  std::vector<float> x, y, z;    // position [m]
  std::vector<float> vx, vy, vz; // velocity [m/s]
  std::vector<float> ax, ay, az; // acceleration [m/s^2] at the current positions
  std::vector<float> density;    // [kg/m^3]
  std::vector<float> pressure;   // [Pa]
  std::vector<std::int64_t> id;  // stable particle identifier
  /// Index this particle had when the state was created; the solver reorders particles by grid
  /// cell every step, and this lets callers return results in the caller's order.
  std::vector<std::uint32_t> originalIndex;

  /// Particles at rest at the given positions, ids 0..n-1.
  static ParticleState atRest(std::vector<float> px, std::vector<float> py, std::vector<float> pz);

  std::size_t size() const { return x.size(); }
  /// Resizes every array to n particles (new entries are zero; originalIndex and id are the index).
  void resize(std::size_t n);
  /// Bytes held by the arrays (capacity), for memory accounting.
  std::size_t bytes() const;
};
} // namespace parafluid
