#pragma once
// What a user sets for the sea: one struct for the Gerstner Ocean source (CPU) and the Gerstner
// Ocean representation (GPU), whose setters write it, so that both build their wave model
// (OceanParameters) in one place.
#include "parafluid/ocean/GerstnerOcean.h"

#include <string>
#include <vector>

namespace parafluid::ocean
{
struct SeaSettings
{
  /// 0: the wave list; 1 calm, 2 swell, 3 storm: presets of eight waves spread about the wind.
  int seaState = 2;
  /// Five numbers per wave: amplitude [m], wavelength [m], direction [degrees], steepness Q
  /// [0, 1], phase [rad].
  std::vector<double> waves;
  double windDirection = 0.0;       // [degrees, counter-clockwise from +x] the wind blows towards
  double windLean = 0.2;            // how far crests lean downwind, 0 to 0.5
  double waterDepth = 0.0;          // [m] uniform depth without a sea floor; 0: deep water
  double maxSteepness = 0.9;        // cap on the summed horizontal steepness (1: the fold limit)
  double breakingDepthRatio = 0.78; // wave height / depth at which waves break (McCowan 1894)
  double breakingStretch = 0.6;     // breaking crest raised by this fraction of its amplitude
  double breakingLean = 0.6;        // [rad] forward tilt of a breaking crest
  double breakingShift = 0.8;       // breaking crest thrown forward by this many amplitudes
  double seaLevel = 0.0;            // [m] height of the still water
  int bathymetryResolution = 256;   // raster points per side for a terrain-surface sea floor

  /// Sets wave `index` of the list (growing it with zeros); false when it held these values.
  bool setWave(int index, const double values[5]);
  /// The wave model's parameters: the preset's waves or the list, deep water at depth 0.
  OceanParameters parameters() const;
  /// Empty when every setting is finite and in its range; else a sentence naming the first bad
  /// one by its property name (WindLean, Waves, ...) and what it allows.
  std::string validate() const;
  /// Every setting as text (full precision): equal keys, equal seas.
  std::string key() const;
};
} // namespace parafluid::ocean
