#pragma once
// Hydraulic erosion on the grid with the virtual-pipe model of Mei, Decaudin & Hu (2007, "Fast
// hydraulic erosion simulation and visualization on GPU", Pacific Graphics): per cell a water
// depth d, a sediment amount s and four outflow fluxes through virtual pipes to the neighbours.
// One step: rain; fluxes accelerated by the difference in water surface height (g dh / l), scaled
// so no cell gives more water than it holds; water depth and velocity from the net flux; capacity
// C = Kc max(sin(tilt), minTilt) |v| min(1, d / capacityDepth) (Mei et al.'s capacity with the depth
// limiter of later implementations, so capacity grows with discharge, as stream power does); dissolve Ks (C - s) dt
// where the water carries less, deposit Kd (s - C) dt where it carries more; evaporation. The sediment moves with the
// water through the same pipes (the fraction of a cell's water that leaves through a pipe takes that fraction of its
// sediment): unlike Mei's semi-Lagrangian advection this conserves sediment exactly, so eroded = deposited + suspended
// at all times. Walls close the grid's edges.
#include "parafluid/terrain/ElevationGrid.h"
#include "parafluid/terrain/ErosionResult.h"

#include <string>
#include <vector>

namespace parafluid::terrain
{
struct PipeSettings
{
  float timeStep = 0.02f;     // [s]
  float rainRate = 0.002f;    // water added to every cell [m/s]
  float gravity = 9.81f;      // [m/s^2]
  float capacity = 0.1f;      // Kc [m of sediment per (m/s)]
  float dissolveRate = 0.5f;  // Ks [1/s]
  float depositRate = 1.0f;   // Kd [1/s]
  float evaporation = 0.015f; // Ke [1/s]
  float minTilt = 0.05f;      // lower bound of sin(tilt) in the capacity, so flat water still carries
  float capacityDepth = 0.5f; // [m] water depth from which the capacity is full; shallower water carries
                              // in proportion to its depth (a thin sheet does not carve like a stream)

  std::string problem() const;
};

class PipeErosion
{
public:
  /// Takes the terrain (grid.problem() must be empty) and starts dry. Throws
  /// std::invalid_argument naming the setting or the terrain's problem.
  PipeErosion(const ElevationGrid& terrain, const PipeSettings& settings);

  void step();
  int steps() const { return this->Steps; }

  /// The terrain as it is now (elevation only; origin and spacing of the input), nx * ny values.
  std::vector<float> elevation() const { return this->unpadded(this->B); }
  /// Water depth [m] and suspended sediment [m] per cell.
  std::vector<float> water() const { return this->unpadded(this->D); }
  std::vector<float> suspendedSediment() const { return this->unpadded(this->S); }
  /// waterFlow: the time-averaged outflow [m^3/s] of each cell; deposited and eroded heights [m].
  ErosionMaps maps() const;
  /// eroded, deposited [m^3] so far; carried: sediment suspended in the water now [m^3].
  SedimentBudget budget() const;

private:
  void computeFluxes();
  void updateWaterAndErode();
  void transportSediment();
  /// Index of cell (i, j) in the padded fields (a ghost ring around the grid).
  std::size_t cell(int i, int j) const
  {
    return static_cast<std::size_t>(j + 1) * static_cast<std::size_t>(this->NX + 2) + static_cast<std::size_t>(i + 1);
  }
  std::vector<float> unpadded(const std::vector<float>& field) const;

  PipeSettings Settings;
  int NX, NY;
  float LX, LY;
  std::vector<float> B, D, S, S2, FL, FR, FB, FT, Q, Delta;
  std::vector<float> Eroded, Deposited, Outflow;
  int Steps = 0;
};
} // namespace parafluid::terrain
