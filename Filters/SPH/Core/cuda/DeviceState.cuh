#pragma once
// Internal to the CUDA backend: the particle state every solver keeps on the GPU, the box's walls
// and the measures read back after each step.
#include "cuda/DeviceMesh.cuh"

#include <array>
#include <cstdint>

namespace parafluid::sph::cuda
{
/// The state on the GPU, one value per particle, sorted by cell.
struct DeviceState
{
  std::uint32_t n = 0;
  float *x, *y, *z, *vx, *vy, *vz, *ax, *ay, *az;
  float* rho;        // density [kg/m^3]
  float* p;          // pressure [Pa]
  float* impulse;    // sum of p dt over an advance [Pa s]
  MeshContacts wall; // the boundary mesh's wall in the sums (distance null: none)
};

/// The box and what its walls do (SPHParameters).
struct DeviceWalls
{
  std::array<float, 6> bounds;
  float support; // h [m]
  std::array<bool, 6> noSlip;
  std::array<bool, 3> periodic;
  float restitution;
  float damping;    // SPHParameters::boundaryDamping, at the mesh
  float gravity[3]; // [m/s^2], as given
};

/// What the time-step control and the blow-up checks read after a step; sums in double.
struct StepMeasures
{
  double compression;     // sum of max(rho - rho0, 0)
  double speedSquaredSum; // sum of |v|^2
  float fastestSquared, largestAccelerationSquared, densest;
  unsigned int nonFinite; // particles with a non-finite position or velocity
  float lo[3], hi[3];     // the particles' bounding box [m]
};
} // namespace parafluid::sph::cuda
