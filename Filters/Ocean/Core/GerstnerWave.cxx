#include "parafluid/ocean/GerstnerWave.h"
#include "parafluid/common/MathConstants.h"

#include <cmath>
#include <stdexcept>

namespace parafluid::ocean
{
namespace
{
}

double GerstnerWave::deepWavenumber() const
{
  return 2.0 * kPi / this->wavelength;
}

void validateWaves(const std::vector<GerstnerWave>& waves)
{
  for (std::size_t i = 0; i < waves.size(); ++i)
  {
    const GerstnerWave& w = waves[i];
    const std::string name = "wave " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(w.amplitude + w.wavelength + w.direction + w.steepness + w.phase))
    {
      throw std::invalid_argument(name + "a value is NaN or infinite");
    }
    if (!(w.amplitude > 0.0))
    {
      throw std::invalid_argument(name + "amplitude must be positive (metres)");
    }
    if (!(w.wavelength > 0.0))
    {
      throw std::invalid_argument(name + "wavelength must be positive (metres)");
    }
    if (w.steepness < 0.0 || w.steepness > 1.0)
    {
      throw std::invalid_argument(name + "steepness Q must lie in [0, 1]");
    }
  }
}

std::vector<GerstnerWave> seaStatePreset(SeaState state, double windDirection)
{
  // Per preset: peak wavelength [m], wave slope k A of the peak wave, steepness Q, half-width of
  // the direction spread [degrees], and the ratio between successive wavelengths.
  double peak = 8.0, slope = 0.04, q = 0.4, spread = 25.0, ratio = 0.8;
  switch (state)
  {
    case SeaState::Calm:
      break;
    case SeaState::Swell:
      peak = 60.0, slope = 0.05, q = 0.5, spread = 8.0, ratio = 0.88;
      break;
    case SeaState::Storm:
      peak = 40.0, slope = 0.12, q = 0.9, spread = 40.0, ratio = 0.75;
      break;
  }
  // Fixed, irregular offsets (a golden-ratio sequence) so that crests never line up in a grid.
  std::vector<GerstnerWave> waves;
  double wavelength = peak;
  for (int i = 0; i < 8; ++i)
  {
    const double u = std::fmod(0.618033988749895 * (i + 1), 1.0); // in [0, 1)
    GerstnerWave w;
    w.wavelength = wavelength;
    // Shorter waves are less steep, as in a wind-sea spectrum; the slopes sum to about 4.4 slope.
    const double k = 2.0 * kPi / wavelength;
    w.amplitude = slope * std::pow(0.82, i) / k;
    w.direction = windDirection + spread * (2.0 * u - 1.0);
    w.steepness = q;
    w.phase = 2.0 * kPi * std::fmod(0.7548776662466927 * (i + 1), 1.0);
    waves.push_back(w);
    wavelength *= ratio;
  }
  return waves;
}

std::vector<GerstnerWave> chooseWaves(int seaState, const std::vector<double>& list, double windDirection)
{
  if (seaState != 0)
  {
    const SeaState state = seaState == 1 ? SeaState::Calm : seaState == 2 ? SeaState::Swell : SeaState::Storm;
    return seaStatePreset(state, windDirection);
  }
  std::vector<GerstnerWave> waves;
  for (std::size_t w = 0; w + 4 < list.size(); w += 5)
  {
    GerstnerWave wave;
    wave.amplitude = list[w];
    wave.wavelength = list[w + 1];
    wave.direction = list[w + 2];
    wave.steepness = list[w + 3];
    wave.phase = list[w + 4];
    waves.push_back(wave);
  }
  return waves;
}
} // namespace parafluid::ocean
