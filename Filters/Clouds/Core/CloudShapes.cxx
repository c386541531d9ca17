#include "parafluid/clouds/CloudShapes.h"

#include "parafluid/terrain/FractalNoise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace parafluid::clouds
{
namespace
{
double smoothStep(double a, double b, double x)
{
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
} // namespace

void fillCloudShapes(StaggeredGrid& g, const CloudShapeParameters& p)
{
  if (!(p.coverage >= 0.0 && p.coverage <= 1.0))
  {
    throw std::invalid_argument("CloudCoverage must lie in [0, 1]");
  }
  if (!(p.featureSize > 0.0) || !std::isfinite(p.featureSize))
  {
    throw std::invalid_argument("CloudFeatureSize must be a positive length");
  }
  if (!(p.base >= 0.0 && p.base < p.top && p.top <= 1.0))
  {
    throw std::invalid_argument("the cloud base must lie below its top, both in [0, 1]");
  }
  if (!std::isfinite(p.density) || !std::isfinite(p.temperature))
  {
    throw std::invalid_argument("the cloud's density and temperature must be finite");
  }
  const terrain::PerlinNoise noise(p.seed);
  terrain::FractalSettings coverage;
  coverage.octaves = 5;
  terrain::FractalSettings billows;
  billows.type = terrain::FractalType::Turbulence;
  billows.octaves = 4;
  // Cloud where the 2-D fBm passes the level that leaves `coverage` of the grid's columns above
  // it: the quantile of the noise's own values over the columns.
  std::vector<float> columns(static_cast<std::size_t>(g.nx) * g.ny);
  for (int j = 0; j < g.ny; ++j)
  {
    for (int i = 0; i < g.nx; ++i)
    {
      const double x = g.origin[0] + (i + 0.5) * g.h, y = g.origin[1] + (j + 0.5) * g.h;
      columns[static_cast<std::size_t>(j) * g.nx + i] =
        terrain::fractal(noise, coverage, static_cast<float>(x / p.featureSize), static_cast<float>(y / p.featureSize));
    }
  }
  std::vector<float> sorted = columns;
  const std::size_t rank =
    std::min(sorted.size() - 1, static_cast<std::size_t>((1.0 - p.coverage) * static_cast<double>(sorted.size())));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(rank), sorted.end());
  const double threshold = p.coverage >= 1.0 ? -1e30 : (p.coverage <= 0.0 ? 1e30 : sorted[rank]);
  const double highest = *std::max_element(columns.begin(), columns.end());
  const double height = g.nz * g.h;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < g.nz; ++k)
  {
    const double z = (k + 0.5) / g.nz;
    for (int j = 0; j < g.ny; ++j)
    {
      for (int i = 0; i < g.nx; ++i)
      {
        const double x = g.origin[0] + (i + 0.5) * g.h, y = g.origin[1] + (j + 0.5) * g.h;
        const double zm = g.origin[2] + z * height;
        // How far inside the covered area (0 at the rim, 1 at the sky's densest column).
        const double c = columns[static_cast<std::size_t>(j) * g.nx + i];
        const double cover = std::clamp((c - threshold) / std::max(highest - threshold, 1e-6), 0.0, 1.0);
        // Puffs a third of the coverage's size, round where the turbulence is low.
        const double puff = 1.0 - terrain::fractal(noise, billows, static_cast<float>(3.0 * x / p.featureSize + 17.3),
                                                   static_cast<float>(3.0 * y / p.featureSize - 5.1),
                                                   static_cast<float>(3.0 * zm / p.featureSize + 2.7));
        // The body rises highest over the middle of a covered patch (a dome over a flat base):
        // the profile is stretched to the patch's local top; the puffs eat into its surface.
        const double localTop = p.base + (p.top - p.base) * std::sqrt(cover);
        const double rel = cover > 0.0 ? (z - p.base) / std::max(localTop - p.base, 1e-6) : 2.0;
        const double dome = smoothStep(0.0, 0.15, rel) * (1.0 - smoothStep(0.45, 1.0, rel));
        const double body = dome - 0.35 * (1.0 - puff);
        const double value = p.density * smoothStep(0.0, 0.25, body);
        const std::size_t id = g.density.index(i, j, k);
        g.density.values[id] = std::max(g.density.values[id], value);
        g.temperature.values[id] += p.temperature * value;
      }
    }
  }
}
} // namespace parafluid::clouds
