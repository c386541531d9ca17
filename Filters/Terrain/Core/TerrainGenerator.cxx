#include "parafluid/terrain/TerrainGenerator.h"

#include "parafluid/terrain/TerrainParameterTables.h"

#include "parafluid/terrain/DiamondSquare.h"

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace parafluid::terrain
{
std::string TerrainSettings::problem() const
{
  const std::string fractalProblem = checkDeclared(fractalParameterTable(), fractal);
  return fractalProblem.empty() ? checkDeclared(terrainParameterTable(), *this) : fractalProblem;
}

namespace
{
/// Rows per progress report (and per parallel region: fewer regions keep both cores busy).
constexpr int kRowsPerReport = 128;

bool forEachRowBlock(int ny, const std::function<bool(double)>& progress, const std::function<void(int)>& row)
{
  for (int start = 0; start < ny; start += kRowsPerReport)
  {
    const int end = start + kRowsPerReport < ny ? start + kRowsPerReport : ny;
#pragma omp parallel for schedule(static)
    for (int j = start; j < end; ++j)
    {
      row(j);
    }
    if (progress && !progress(static_cast<double>(end) / ny))
    {
      return false;
    }
  }
  return true;
}
} // namespace

bool generateTerrain(const TerrainSettings& s, ElevationGrid& grid, const std::function<bool(double)>& progress)
{
  const std::string problem = s.problem();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  if (grid.nx < 2 || grid.ny < 2)
  {
    throw std::invalid_argument("Resolution must be at least 2 x 2");
  }
  grid.elevation.assign(grid.size(), 0.0f);
  const auto scale = static_cast<float>(s.heightScale), base = static_cast<float>(s.baseHeight);
  if (s.method == TerrainMethod::DiamondSquare)
  {
    const int levels = diamondSquareLevels(grid.nx > grid.ny ? grid.nx : grid.ny);
    if (levels > 15)
    {
      throw std::invalid_argument("diamond-square handles at most 32769 samples per side");
    }
    const std::vector<float> values = diamondSquare(levels, s.roughness, s.seed);
    const int size = (1 << levels) + 1;
    for (int j = 0; j < grid.ny; ++j)
    {
      for (int i = 0; i < grid.nx; ++i)
      {
        grid.elevation[grid.index(i, j)] = base + scale * values[static_cast<std::size_t>(j) * size + i];
      }
    }
    return !progress || progress(1.0);
  }

  const PerlinNoise noise(s.seed);
  const FractalSettings& f = s.fractal;
  // Coordinates in units of the first octave's wavelength. With an integer lacunarity every octave
  // repeats after 256 units, so the origin is taken modulo that period: far-away world
  // coordinates keep their float precision and give the same terrain.
  double ox = grid.x0 / s.featureSize, oy = grid.y0 / s.featureSize;
  if (f.lacunarity == std::round(f.lacunarity))
  {
    ox = std::fmod(ox, 256.0), oy = std::fmod(oy, 256.0);
  }
  const double sx = grid.dx / s.featureSize, sy = grid.dy / s.featureSize;
  // The finest octave's lattice index must fit an int (and keep sub-cell float precision).
  const double reach =
    (std::fabs(ox) + std::fabs(oy) + sx * grid.nx + sy * grid.ny + std::fabs(s.warpStrength) / s.featureSize + 8.0) *
    std::pow(static_cast<double>(f.lacunarity), f.octaves - 1);
  const double warpReach = s.warpStrength == 0.0
                             ? 0.0
                             : (std::fabs(ox) + std::fabs(oy) + sx * grid.nx + sy * grid.ny + 8.0) * s.featureSize /
                                 s.warpScale * std::pow(static_cast<double>(f.lacunarity), s.warpOctaves - 1);
  if (!(reach < 1e6 && warpReach < 1e6))
  {
    throw std::invalid_argument(
      "the finest octave would sample the noise " + std::to_string(reach) +
      " lattice cells from the origin, beyond float precision: lower Octaves or Lacunarity, or raise FeatureSize");
  }
  if (s.warpStrength == 0.0)
  {
    return forEachRowBlock(grid.ny, progress,
                           [&](int j)
                           {
                             float* row = grid.elevation.data() + grid.index(0, j);
                             fractalRow(noise, f, static_cast<float>(ox), static_cast<float>(sx),
                                        static_cast<float>(oy + sy * j), grid.nx, row);
                             for (int i = 0; i < grid.nx; ++i)
                             {
                               row[i] = base + scale * row[i];
                             }
                           });
  }
  // The warp: two fBm of their own seed, read at unrelated offsets for x and y.
  const PerlinNoise warpNoise(splitMix64(s.seed ^ 0x77617270ull));
  FractalSettings w;
  w.octaves = s.warpOctaves;
  w.lacunarity = f.lacunarity;
  w.persistence = f.persistence;
  const auto strength = static_cast<float>(s.warpStrength / s.featureSize);
  const auto toWarp = static_cast<float>(s.featureSize / s.warpScale);
  return forEachRowBlock(grid.ny, progress,
                         [&](int j)
                         {
                           const std::size_t n = static_cast<std::size_t>(grid.nx);
                           std::vector<float> x(n), y(n), u(n), v(n), wx(n), wy(n);
                           const auto row = static_cast<float>(oy + sy * j);
                           for (std::size_t i = 0; i < n; ++i)
                           {
                             x[i] = static_cast<float>(ox + sx * static_cast<double>(i));
                             u[i] = x[i] * toWarp, v[i] = row * toWarp;
                           }
                           fractalPoints(warpNoise, w, u.data(), v.data(), grid.nx, wx.data());
                           for (std::size_t i = 0; i < n; ++i)
                           {
                             u[i] += 5.2f, v[i] += 1.3f;
                           }
                           fractalPoints(warpNoise, w, u.data(), v.data(), grid.nx, wy.data());
                           for (std::size_t i = 0; i < n; ++i)
                           {
                             u[i] = x[i] + strength * wx[i], v[i] = row + strength * wy[i];
                           }
                           float* out = grid.elevation.data() + grid.index(0, j);
                           fractalPoints(noise, f, u.data(), v.data(), grid.nx, out);
                           for (std::size_t i = 0; i < n; ++i)
                           {
                             out[i] = base + scale * out[i];
                           }
                         });
}
} // namespace parafluid::terrain
