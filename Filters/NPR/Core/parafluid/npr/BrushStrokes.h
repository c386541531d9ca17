#pragma once
// Where painted brush strokes go over a particle fluid: along its flow lines where the flow is fast
// enough for a line to be at least one stroke long, and, where it is slower, strokes of one fixed
// length laid on a grid so that still water is filled as evenly as moving water. Each stroke
// carries a colour value (e.g. the density at its seed particle).
#include "parafluid/npr/FlowLines.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace parafluid::npr
{
struct BrushStrokeParameters
{
  FlowLineParameters flow;   // the flow lines strokes follow (their seeds, duration, budget)
  double strokeLength = 0.0; // [m] the fixed strokes' length, and the shortest flow stroke kept
  double fillSpacing = 0.0;  // [m] one fixed stroke per cube of this side where the flow is slow
  std::size_t maxStrokes = 20000;
};

/// Empty when usable, else what is wrong with which parameter.
std::string validate(const BrushStrokeParameters& parameters);

struct BrushStrokeSet
{
  std::vector<float> points;          // x, y, z per point
  std::vector<std::uint32_t> offsets; // stroke s is points [offsets[s], offsets[s + 1])
  std::vector<float> value;           // per stroke: the colour value at its seed particle
  std::vector<std::uint32_t> seed;    // per stroke: index of its seed particle
  std::vector<std::uint8_t> fixed;    // per stroke: 1 for a fixed-length stroke of a slow region
  std::size_t strokeCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

/// Lays strokes over n particles (positions and velocities x, y, z interleaved; `value` one per
/// particle, or null for 0). A particle is slow when speed x flow.lineDuration < strokeLength:
/// its flow line would be shorter than a stroke. Flow lines start from every flow.seedStride-th
/// fast particle, thinned evenly to at most 2 x maxStrokes seeds (the work follows the budget,
/// not the particle count), and are kept when at least strokeLength long; flow.maxLines bounds
/// the lines traced. Flow strokes come first (in seed order),
/// then fixed strokes, up to maxStrokes in all. A fixed stroke is centred on the slow particle
/// nearest its grid cube's centre and points along its velocity, or, where the particle is at
/// rest, along a horizontal (x-y) direction that varies from cube to cube. progress may return
/// false to abandon (the result is then empty). Throws std::invalid_argument for bad parameters
/// or NaN/infinite positions.
BrushStrokeSet layoutBrushStrokes(const float* xyz, const float* velocity, const float* value, std::size_t n,
                                  const BrushStrokeParameters& parameters,
                                  const std::function<bool(double)>& progress = {});
} // namespace parafluid::npr
