#pragma once
// What a rain shower is: where it falls from, how hard, how many drops are drawn, and the wind.
#include <array>
#include <cstdint>
#include <string>

namespace parafluid::rain
{
struct RainParameters
{
  /// The precipitation area: x0, x1, y0, y1 [m], a horizontal rectangle at `height` [m] (above the
  /// highest ground under it), cut into cells[0] x cells[1] cells, each with its own drops.
  std::array<double, 4> bounds{ 0.0, 1.0, 0.0, 1.0 };
  double height = 10.0;
  std::array<int, 2> cells{ 64, 64 };
  /// Rainfall rate [mm/h] (light rain 1, heavy 10-50, cloudburst 100+).
  double rainfallRate = 10.0;
  /// Drops drawn per real drop in the air (<= 1): fewer drops drawn, each carrying more water, so
  /// the water delivered does not change.
  double dropsPerRealDrop = 1e-3;
  /// Horizontal wind [m/s]: drops drift with it.
  std::array<double, 2> wind{ 0.0, 0.0 };
  /// Each drop's own horizontal speed is the wind plus a uniform jitter of up to this [m/s].
  double velocityJitter = 0.2;
  /// true: drops fall at the terminal speed of their diameter (Atlas et al. 1973); false: the seed
  /// method's ballistic drops, thrown down at `initialSpeed` [m/s] and accelerated by gravity.
  bool terminalVelocity = true;
  double initialSpeed = 2.0;
  double gravity = 9.81; // [m/s^2]
  /// The shower lasts this long [s] (0: forever): drops born later do not exist.
  double duration = 0.0;
  std::uint64_t seed = 1;

  /// Empty when valid, else what is wrong, naming the property.
  std::string validate() const;
};
} // namespace parafluid::rain
