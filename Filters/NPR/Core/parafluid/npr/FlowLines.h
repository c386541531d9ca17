#pragma once
// Short flow lines through the particles' velocity field for illustration: from each seed, a
// polyline of a fixed number of points integrated over a fixed time (RK2 or RK4) through the
// velocity interpolated with the poly6 kernel (Shepard-normalised, so a uniform flow is
// reproduced exactly and the edge of the fluid does not slow the lines down), so a line's length
// follows the local speed. The lines that are long and curved, ranked by length x turning, are
// kept up to a budget.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace parafluid::npr
{
enum class FlowIntegrator
{
  RK2, // midpoint
  RK4
};

struct FlowLineParameters
{
  double kernelRadius = 0.0; // h [m]: support of the interpolation kernel
  int seedStride = 10;       // with no explicit seeds: every k-th particle
  int pointsPerLine = 16;    // points of each line (the line has pointsPerLine - 1 steps)
  double lineDuration = 0.1; // [s] time integrated along each line
  FlowIntegrator integrator = FlowIntegrator::RK4;
  std::size_t maxLines = 2000; // budget: the best-ranked lines kept
};

/// Empty when usable, else what is wrong with which parameter.
std::string validate(const FlowLineParameters& parameters);

struct FlowLineSet
{
  std::vector<float> points;          // x, y, z per point
  std::vector<std::uint32_t> offsets; // line l is points [offsets[l], offsets[l + 1])
  std::vector<float> speed;           // |v| [m/s] per point
  std::vector<float> curvature;       // [1/m] per point: turning angle over the mean adjacent step
  std::vector<float> length;          // [m] per line
  std::vector<float> turning;         // [rad] per line: summed angle between successive steps
  std::vector<std::uint32_t> seed;    // per line: index of its seed
  std::size_t lineCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

/// Traces lines through n particles (positions and velocities, x, y, z interleaved). Seeds are
/// `seeds` (x, y, z interleaved, seedCount of them) when given, else every seedStride-th
/// particle. A line stops early where it leaves the kernel's reach of every particle; lines of
/// fewer than two points are dropped. progress(fraction) may return false to abandon (the result
/// is then empty). Throws std::invalid_argument for bad parameters or NaN/infinite positions.
FlowLineSet traceFlowLines(const float* xyz, const float* velocity, std::size_t n, const FlowLineParameters& parameters,
                           const float* seeds = nullptr, std::size_t seedCount = 0,
                           const std::function<bool(double)>& progress = {});
} // namespace parafluid::npr
