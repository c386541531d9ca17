#pragma once
// What an erosion run leaves besides the new elevation: per-sample maps a user can colour by, and
// the totals that show the sediment budget closes.
#include <vector>

namespace parafluid::terrain
{
struct ErosionMaps
{
  std::vector<float> waterFlow;         // drop visits per sample (droplets) or water flux [m^3/s] (pipes)
  std::vector<float> sedimentDeposited; // height of sediment laid down [m]
  std::vector<float> erodedDepth;       // height of ground taken away [m]
};

struct SedimentBudget
{
  double eroded = 0.0;    // volume taken from the ground [m^3]
  double deposited = 0.0; // volume laid down [m^3]
  double carried = 0.0;   // volume still in the water (or carried off the grid) at the end [m^3]
};
} // namespace parafluid::terrain
