#include "parafluid/ocean/SeaSettings.h"

#include <algorithm>
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
