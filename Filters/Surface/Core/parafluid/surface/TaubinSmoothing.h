#pragma once
// Taubin's lambda|mu smoothing (Taubin 1995): a shrinking Laplacian step (lambda > 0) followed by
// an inflating one (mu < -lambda) removes the high-frequency bumps of a particle surface while
// keeping its volume, where plain Laplacian smoothing shrinks every convex blob.
#include <cstdint>
#include <vector>

namespace parafluid::surface
{
/// Smooths `points` (x, y, z per vertex) of the triangle mesh in place with `iterations`
/// lambda|mu pairs, using the umbrella (mean of edge neighbours) Laplacian. Deterministic for any
/// number of threads. Vertices no triangle uses stay where they are.
void taubinSmooth(std::vector<float>& points, const std::vector<std::uint32_t>& triangles, int iterations,
                  float lambda = 0.5f, float mu = -0.53f);
} // namespace parafluid::surface
