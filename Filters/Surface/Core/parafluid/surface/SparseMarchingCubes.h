#pragma once
// Marching cubes over a SparseDensityField, visiting only blocks the iso surface can pass through.
//
// Each grid edge the surface crosses gets one vertex, owned by the block of the edge's lower end;
// cells (owned by the block of their lower corner) look up the vertices of edges owned by the
// blocks above them, so the mesh is one shared-vertex, watertight surface with no seams between
// blocks. Blocks, cells and edges are numbered in a fixed order and counted before they are
// written (prefix sums), so the output is the same for any number of threads.
#include "parafluid/surface/SparseDensityField.h"
#include "parafluid/surface/SurfaceMesh.h"

namespace parafluid::surface
{
struct MarchingCubesStatistics
{
  std::size_t surfaceBlocks = 0; // blocks whose cells were polygonised
  std::size_t bytes = 0;         // working memory beyond the field and the output mesh
};

/// The surface phi = field.isoValue() (> 0), oriented so normals point to lower phi (out of the
/// fluid). Vertex normals are -grad phi (central differences, interpolated along the edge) when
/// `normals` is set.
SurfaceMesh sparseMarchingCubes(const SparseDensityField& field, bool normals,
                                MarchingCubesStatistics* statistics = nullptr);
} // namespace parafluid::surface
