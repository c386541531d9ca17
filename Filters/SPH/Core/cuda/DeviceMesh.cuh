#pragma once
// Internal to the CUDA backend: the boundary mesh and its wall table in GPU memory, and each
// particle's nearest mesh point found on the GPU (SPHSolver::findMeshWalls), with the queries the
// CPU runs (TriangleMeshView, MeshWallTableView) over the device copies.
#include "cuda/DeviceBuffer.h"
#include "parafluid/common/TriangleBoundary.h"
#include "private/MeshWall.h"

#include <cuda_runtime.h>

#include <cstdint>

namespace parafluid::sph::cuda
{
/// Each particle's contact with the mesh, on the GPU (null pointers: no mesh wall in the sums).
struct MeshContacts
{
  detail::MeshWallTableView table; // over device arrays
  float* distance = nullptr;       // to the nearest mesh point, reach when none [m]
  float* normal = nullptr;         // 3 n: x, y and z of the unit vector from it to the particle
  std::uint32_t* triangle = nullptr;
  float* wallSum = nullptr; // δ-SPH's DeltaSPHSolver::WallSum
};

class DeviceMesh
{
public:
  /// Copies `mesh` and (when not null) the wall table to the GPU; the copies finish on `stream`.
  void upload(const TriangleBoundary& mesh, const detail::MeshWallTable* table, cudaStream_t stream);
  /// The mesh's queries over the device arrays (triangleCount 0 before upload).
  const TriangleMeshView& view() const { return this->View; }
  /// The wall table over the device arrays (samples 0 without one).
  const detail::MeshWallTableView& table() const { return this->Table; }
  std::size_t bytes() const;

private:
  DeviceBuffer<float> Points, VertexNormals, FaceNormals, Sum, Slope, Count;
  DeviceBuffer<std::uint32_t> Triangles, CellStart, CellTriangles;
  TriangleMeshView View;
  detail::MeshWallTableView Table;
};

/// Each of the n particles' nearest point of `mesh` within the table's reach, as
/// SPHSolver::findMeshWalls: c.triangle holds a hint on entry (any value >= the triangle count
/// for none) and the triangle found on exit; a particle behind the mesh gets none.
void launchFindMeshWalls(const float* x, const float* y, const float* z, std::uint32_t n, const TriangleMeshView& mesh,
                         const MeshContacts& c, cudaStream_t stream);
/// c.wallSum = the table's sum at each particle's distance (δ-SPH's start).
void launchStartWallSums(const MeshContacts& c, std::uint32_t n, cudaStream_t stream);
} // namespace parafluid::sph::cuda
