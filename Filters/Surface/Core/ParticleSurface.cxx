#include "parafluid/surface/ParticleSurface.h"

#include "parafluid/surface/SparseMarchingCubes.h"
#include "parafluid/surface/TaubinSmoothing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace parafluid::surface
{
namespace
{
double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
} // namespace

std::string validate(const ParticleSurfaceParameters& p)
{
  std::ostringstream why;
  if (!(p.particleSpacing > 0.0) || !std::isfinite(p.particleSpacing))
  {
    why << "ParticleSpacing must be a positive length (got " << p.particleSpacing << " m)";
  }
  else if (!(p.cellSize >= 0.05 && p.cellSize <= 10.0))
  {
    why << "CellSize must be between 0.05 and 10 particle spacings (got " << p.cellSize << ")";
  }
  else if (!(p.kernelRadius >= 1.0 && p.kernelRadius <= 10.0))
  {
    why << "KernelRadius must be between 1 and 10 particle spacings (got " << p.kernelRadius << ")";
  }
  else if (!(p.isoValue > 0.0 && p.isoValue < 1.0))
  {
    why << "IsoValue must lie between 0 and 1, exclusive (got " << p.isoValue
        << "); 0.5 is the edge of the particles' volume";
  }
  else if (p.smoothingIterations < 0 || p.smoothingIterations > 1000)
  {
    why << "Smoothing must be between 0 and 1000 iterations (got " << p.smoothingIterations << ")";
  }
  return why.str();
}

SurfaceMesh ParticleSurface::extract(const float* xyz, std::size_t n, const ParticleSurfaceParameters& p,
                                     const Progress& progress)
{
  const std::string problem = validate(p);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  this->Statistics = ParticleSurfaceStatistics();
  const double d = p.particleSpacing;
  auto t0 = std::chrono::steady_clock::now();
  this->Field.build(xyz, n, p.cellSize * d, p.kernelRadius * d, d * d * d, p.isoValue);
  this->Statistics.fieldSeconds = secondsSince(t0);
  this->Statistics.allocatedBlocks = this->Field.blockCount();
  if (n == 0 || (progress && !progress(0.6)))
  {
    return SurfaceMesh();
  }
  t0 = std::chrono::steady_clock::now();
  MarchingCubesStatistics mc;
  SurfaceMesh mesh = sparseMarchingCubes(this->Field, p.computeNormals, &mc);
  this->Statistics.meshSeconds = secondsSince(t0);
  this->Statistics.surfaceBlocks = mc.surfaceBlocks;
  this->Statistics.workingBytes = std::max(this->Field.sortPeakBytes(), this->Field.bytes() + mc.bytes);
  // From here on only the particles are read (interpolate(), meanLevelSetDistance()).
  this->Field.releaseValues();
  if (progress && !progress(0.85))
  {
    return SurfaceMesh();
  }
  t0 = std::chrono::steady_clock::now();
  taubinSmooth(mesh.points, mesh.triangles, p.smoothingIterations);
  this->Statistics.smoothSeconds = secondsSince(t0);
  if (p.smoothingIterations > 0)
  {
    // Neighbour lists (two uint32 per triangle corner, then unique) and the second point buffer.
    const std::size_t smoothing = mesh.triangles.size() * 2 * sizeof(std::uint32_t) +
                                  mesh.points.size() * sizeof(float) + (mesh.vertexCount() + 1) * sizeof(std::uint32_t);
    this->Statistics.workingBytes = std::max(this->Statistics.workingBytes, this->Field.bytes() + smoothing);
  }
  if (progress)
  {
    progress(1.0);
  }
  return mesh;
}

std::vector<float> ParticleSurface::interpolate(const SurfaceMesh& mesh, const float* values, int components) const
{
  const std::size_t nv = mesh.vertexCount();
  std::vector<float> out(nv * static_cast<std::size_t>(components), 0.0f);
  if (components <= 0 || this->Field.blockCount() == 0)
  {
    return out;
  }
  // Distances in cells, as the field keeps the particles.
  const double c = this->Field.cellSize();
  const double r = this->Field.kernelRadius() / c;
  const double r2 = r * r;
  const double* origin = this->Field.origin();
  const auto& sortedIndex = this->Field.sortedIndex();
  const long long count = static_cast<long long>(nv);
#pragma omp parallel
  {
    std::vector<double> sum(static_cast<std::size_t>(components));
#pragma omp for schedule(dynamic, 256)
    for (long long v = 0; v < count; ++v)
    {
      const double x[3] = { (mesh.points[3 * v] - origin[0]) / c, (mesh.points[3 * v + 1] - origin[1]) / c,
                            (mesh.points[3 * v + 2] - origin[2]) / c };
      std::fill(sum.begin(), sum.end(), 0.0);
      double weight = 0.0;
      this->Field.forEachParticleNear(x,
                                      [&](std::uint32_t k, double, double, double, double s2)
                                      {
                                        const double t = r2 - s2;
                                        const double w = t * t * t; // poly6, unnormalised: the normalisation cancels
                                        weight += w;
                                        const float* value =
                                          values + static_cast<std::size_t>(sortedIndex[k]) * components;
                                        for (int comp = 0; comp < components; ++comp)
                                        {
                                          sum[comp] += w * value[comp];
                                        }
                                      });
      if (weight > 0.0)
      {
        for (int comp = 0; comp < components; ++comp)
        {
          out[static_cast<std::size_t>(v) * components + comp] = static_cast<float>(sum[comp] / weight);
        }
      }
    }
  }
  return out;
}

double ParticleSurface::meanLevelSetDistance(const SurfaceMesh& mesh, std::size_t samples) const
{
  const std::size_t nv = mesh.vertexCount();
  if (nv == 0 || samples == 0 || this->Field.blockCount() == 0)
  {
    return 0.0;
  }
  const std::size_t stride = std::max<std::size_t>(1, nv / samples);
  const long long count = static_cast<long long>((nv + stride - 1) / stride);
  const double iso = this->Field.isoValue();
  double total = 0.0;
#pragma omp parallel for reduction(+ : total) schedule(dynamic, 64)
  for (long long i = 0; i < count; ++i)
  {
    const std::size_t v = static_cast<std::size_t>(i) * stride;
    const double p[3] = { mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2] };
    double g[3];
    const double phi = this->Field.evaluate(p, g);
    const double slope = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    // First order in the distance, which is a small fraction of a cell here.
    total += slope > 0.0 ? std::abs(phi - iso) / slope : 0.0;
  }
  return total / static_cast<double>(count);
}

void ParticleSurface::release()
{
  this->Field = SparseDensityField();
}
} // namespace parafluid::surface
