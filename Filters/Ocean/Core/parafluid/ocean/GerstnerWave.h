#pragma once
// One Gerstner (trochoidal) wave and the preset wave sets a user starts from.
#include <string>
#include <vector>

namespace parafluid::ocean
{
struct GerstnerWave
{
  double amplitude = 0.5;   // [m] half the crest-to-trough height, in deep water
  double wavelength = 20.0; // [m] crest-to-crest distance in deep water
  double direction = 0.0;   // [degrees] direction of travel, counter-clockwise from +x
  double steepness = 0.5;   // Q in [0, 1]: 0 is a sine wave, 1 the sharpest crest a lone wave takes
  double phase = 0.0;       // [rad]

  double deepWavenumber() const;
};

/// Throws std::invalid_argument naming the wave and the field for a non-positive amplitude or
/// wavelength, a steepness outside [0, 1] or a non-finite value.
void validateWaves(const std::vector<GerstnerWave>& waves);

enum class SeaState
{
  Calm,  // short, low wind waves
  Swell, // long, regular waves from a distant storm, narrow spread of directions
  Storm  // steep, broad-banded, directions spread around the wind
};

/// Eight waves around a peak wavelength, directions spread about `windDirection` [degrees];
/// the summed Q k A stays below 0.5 (storm), so presets never fold in deep water.
std::vector<GerstnerWave> seaStatePreset(SeaState state, double windDirection);

/// The waves a Gerstner Ocean source or representation draws: `seaState` 0 takes the wave list
/// (five numbers per wave: amplitude, wavelength, direction, steepness, phase; a trailing partial
/// wave is ignored), 1..3 the Calm, Swell and Storm presets about `windDirection`.
std::vector<GerstnerWave> chooseWaves(int seaState, const std::vector<double>& list, double windDirection);
} // namespace parafluid::ocean
