#pragma once
// Hydraulic erosion by droplets (after Beyer 2015, "Implementation of a method for hydraulic
// erosion", TU Munich, and Mei et al.'s capacity law): each drop starts at a random point, moves
// one cell per step along its direction, which turns towards steepest descent by 1 - inertia,
// gains speed going down, and carries sediment up to a capacity
//   C = capacity * max(-dh, minSlope) * speed * water,
// eroding the ground under an erosion brush where it carries less, depositing where it carries
// more or climbs, and losing water to evaporation. Heights enter in units of the grid spacing, so
// a terrain scaled as a whole erodes the same way.
//
// Deterministic in parallel: drops run in batches of a fixed size; each drop of a batch traces
// its path on the terrain as it was at the batch's start (in parallel), recording what it erodes
// and deposits; the records are then applied in drop order. Each drop's start comes from a hash
// of (seed, drop index). So the result depends on the seed and the batch size, never on threads.
#include "parafluid/terrain/ElevationGrid.h"
#include "parafluid/terrain/ErosionResult.h"

#include <cstdint>
#include <functional>
#include <string>

namespace parafluid::terrain
{
struct DropletSettings
{
  long long drops = 200000;
  float inertia = 0.05f;     // how much of its direction a drop keeps per step (0..1)
  float capacity = 4.0f;     // sediment capacity factor
  float erodeRate = 0.05f;   // fraction of the spare capacity taken per step (0..1); Beyer's 0.3 was for
                             // heights normalised to [0, 1], far flatter per cell than real slopes
  float depositRate = 0.3f;  // fraction of the surplus laid down per step (0..1)
  float evaporation = 0.01f; // fraction of water lost per step (0..1)
  float radius = 3.0f;       // erosion brush radius [cells]
  float gravity = 4.0f;      // speed gained per unit drop in height (dimensionless, Beyer's value)
  float minSlope = 0.01f;    // slope below which capacity stops falling
  int maxSteps = 64;         // a drop's lifetime [steps]
  std::uint64_t seed = 0;
  int batchSize = 1024; // drops traced against one snapshot (part of the result's definition)

  std::string problem() const;
};

/// Erodes grid.elevation in place; maps get nx*ny values each. `progress(fraction)` returning
/// false stops after the current batch (the terrain is then consistent, with fewer drops).
SedimentBudget erodeWithDroplets(const DropletSettings& settings, ElevationGrid& grid, ErosionMaps& maps,
                                 const std::function<bool(double)>& progress = {});
} // namespace parafluid::terrain
