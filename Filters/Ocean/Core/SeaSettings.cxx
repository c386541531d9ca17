#include "parafluid/ocean/SeaSettings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace parafluid::ocean
{
bool SeaSettings::setWave(int index, const double values[5])
{
  if (index < 0)
  {
    return false;
  }
  const std::size_t needed = 5 * (static_cast<std::size_t>(index) + 1);
  if (this->waves.size() < needed)
  {
    this->waves.resize(needed, 0.0);
  }
  if (std::equal(values, values + 5, this->waves.begin() + 5 * index))
  {
    return false;
  }
  std::copy(values, values + 5, this->waves.begin() + 5 * index);
  return true;
}

OceanParameters SeaSettings::parameters() const
{
  OceanParameters p;
  p.waves = chooseWaves(this->seaState, this->waves, this->windDirection);
  p.depth = this->waterDepth > 0.0 ? this->waterDepth : kDeepWater;
  p.maxSteepness = this->maxSteepness;
  p.windDirection = this->windDirection;
  p.windLean = this->windLean;
  p.breakingDepthRatio = this->breakingDepthRatio;
  p.breakingStretch = this->breakingStretch;
  p.breakingLean = this->breakingLean;
  p.breakingShift = this->breakingShift;
  return p;
}

namespace
{
/// Empty when v is finite and in [lo, hi]; else why not, naming the property.
std::string outside(const char* name, double v, double lo, double hi)
{
  if (std::isfinite(v) && v >= lo && v <= hi)
  {
    return {};
  }
  std::ostringstream text;
  text << name << " = " << v << " is not allowed: it must be a finite number from " << lo << " to " << hi;
  return text.str();
}
} // namespace

std::string SeaSettings::validate() const
{
  // Distances up to 1e7 m (a sea 10000 km across) and angles up to 1e6 degrees: beyond them float
  // phases lose every digit and the output would be noise.
  const std::string checks[] = {
    outside("WindDirection", this->windDirection, -1e6, 1e6),
    outside("WindLean", this->windLean, 0.0, 0.5),
    outside("WaterDepth", this->waterDepth, 0.0, 1e5),
    outside("MaxSteepness", this->maxSteepness, 0.01, 1.0),
    outside("BreakingDepthRatio", this->breakingDepthRatio, 0.01, 10.0),
    outside("BreakingStretch", this->breakingStretch, 0.0, 10.0),
    outside("BreakingLean", this->breakingLean, 0.0, 1.4),
    outside("BreakingShift", this->breakingShift, 0.0, 10.0),
    outside("SeaLevel", this->seaLevel, -1e7, 1e7),
    outside("BathymetryResolution", this->bathymetryResolution, 2, 8192),
  };
  for (const std::string& problem : checks)
  {
    if (!problem.empty())
    {
      return problem;
    }
  }
  for (std::size_t w = 0; w + 4 < this->waves.size(); w += 5)
  {
    const double* wave = &this->waves[w];
    const std::string problem =
      outside("Waves (amplitude)", wave[0], 0.0, 1e3) + outside("Waves (wavelength)", wave[1], 1e-3, 1e7) +
      outside("Waves (direction)", wave[2], -1e6, 1e6) + outside("Waves (steepness)", wave[3], 0.0, 1.0) +
      outside("Waves (phase)", wave[4], -1e6, 1e6);
    if (!problem.empty())
    {
      return problem + " (wave " + std::to_string(w / 5) + ")";
    }
  }
  return {};
}

std::string SeaSettings::key() const
{
  std::ostringstream key;
  key.precision(17);
  key << this->seaState << ' ' << this->windDirection << ' ' << this->windLean << ' ' << this->waterDepth << ' '
      << this->maxSteepness << ' ' << this->breakingDepthRatio << ' ' << this->breakingStretch << ' '
      << this->breakingLean << ' ' << this->breakingShift << ' ' << this->seaLevel << ' ' << this->bathymetryResolution;
  for (double w : this->waves)
  {
    key << ' ' << w;
  }
  return key.str();
}
} // namespace parafluid::ocean
