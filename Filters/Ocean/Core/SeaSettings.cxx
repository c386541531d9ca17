#include "parafluid/ocean/SeaSettings.h"

#include "parafluid/ocean/SeaParameterTable.h"

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
  return checkNumber(name, "", lo, hi, v);
}
} // namespace

std::string SeaSettings::validate() const
{
  const std::string declared = checkDeclared(seaParameterTable(), *this);
  if (!declared.empty())
  {
    return declared;
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
