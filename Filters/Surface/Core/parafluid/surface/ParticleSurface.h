#pragma once
// Particles -> triangle surface: covered-volume field on a sparse grid (SparseDensityField),
// marching cubes over the blocks the surface passes through (SparseMarchingCubes), Taubin
// smoothing, and Shepard interpolation of particle arrays to the vertices.
#include "parafluid/surface/SparseDensityField.h"
#include "parafluid/surface/SurfaceMesh.h"

#include <functional>
#include <string>

namespace parafluid::surface
{
struct ParticleSurfaceParameters
{
  double particleSpacing = 0.0; // d [m]: the lattice spacing the particles were seeded at
  double cellSize = 0.5;        // grid cell edge, in d
  double kernelRadius = 3.0;    // poly6 support radius, in d (wider: smoother, but a convex
                                // blob of radius R shrinks by about r^2 / (11 R))
  double isoValue = 0.5;        // level of the covered-volume fraction phi (1 inside, 0 outside)
  int smoothingIterations = 0;  // Taubin lambda|mu pairs
  bool computeNormals = true;
};

/// Returns an empty string when the parameters are usable, else what is wrong with which one.
std::string validate(const ParticleSurfaceParameters& parameters);

struct ParticleSurfaceStatistics
{
  std::size_t allocatedBlocks = 0;
  std::size_t surfaceBlocks = 0;
  std::size_t workingBytes = 0; // peak bytes held beyond the input and the output mesh
  double fieldSeconds = 0.0, meshSeconds = 0.0, smoothSeconds = 0.0;
};

class ParticleSurface
{
public:
  /// progress(fraction) is called between stages; returning false abandons the extraction (the
  /// result is then an empty mesh).
  using Progress = std::function<bool(double)>;

  /// Throws std::invalid_argument with validate()'s message for bad parameters, and for NaN or
  /// infinite positions. Zero particles give an empty mesh.
  SurfaceMesh extract(const float* xyz, std::size_t n, const ParticleSurfaceParameters& parameters,
                      const Progress& progress = {});

  /// Kernel-weighted (Shepard) average of a particle array at each vertex of `mesh`, using the
  /// particles of the last extract() (which must still be alive and unchanged): values holds
  /// `components` floats per particle; the result holds as many per vertex.
  std::vector<float> interpolate(const SurfaceMesh& mesh, const float* values, int components) const;

  /// Mean distance [m] of `mesh`'s vertices (every k-th, about `samples` of them) from the exact
  /// iso surface of the last extract()'s field, |phi - iso| / |grad phi| with phi summed over the
  /// particles: the part of the surface's error that the grid makes (the rest is the field's own).
  double meanLevelSetDistance(const SurfaceMesh& mesh, std::size_t samples = 2000) const;

  const ParticleSurfaceStatistics& statistics() const { return this->Statistics; }
  /// Releases the field (kept after extract() for interpolate()).
  void release();

private:
  SparseDensityField Field;
  ParticleSurfaceStatistics Statistics;
};
} // namespace parafluid::surface
