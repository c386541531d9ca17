#include "parafluid/terrain/FractalNoise.h"

#include <cmath>

namespace parafluid::terrain
{
namespace
{
/// Per-octave shift (irrational multiples) so the octaves' lattice points never coincide.
constexpr float kOctaveShiftX = 0.3183099f; // 1/pi
constexpr float kOctaveShiftY = 0.7071068f; // 1/sqrt 2
constexpr float kOctaveShiftZ = 0.5772157f; // Euler-Mascheroni

float normalisation(const FractalSettings& s)
{
  float sum = 0.0f, amplitude = 1.0f;
  for (int o = 0; o < s.octaves; ++o)
  {
    sum += amplitude;
    amplitude *= s.persistence;
  }
  return sum > 0.0f ? 1.0f / sum : 0.0f;
}

/// One octave's contribution from its raw noise value n; `weight` carries the ridged weighting.
inline float octaveTerm(const FractalSettings& s, float n, float& weight)
{
  switch (s.type)
  {
    case FractalType::Turbulence:
      return std::fabs(n);
    case FractalType::Ridged:
    {
      float signal = s.ridgeOffset - std::fabs(n);
      signal *= signal * weight;
      weight = signal * s.ridgeGain;
      weight = weight < 0.0f ? 0.0f : (weight > 1.0f ? 1.0f : weight);
      return signal;
    }
    default:
      return n;
  }
}
} // namespace

float fractal(const PerlinNoise& noise, const FractalSettings& s, float x, float y)
{
  float sum = 0.0f, amplitude = 1.0f, frequency = 1.0f, weight = 1.0f;
  for (int o = 0; o < s.octaves; ++o)
  {
    const float n = noise.noise(x * frequency + kOctaveShiftX * o, y * frequency + kOctaveShiftY * o);
    sum += amplitude * octaveTerm(s, n, weight);
    amplitude *= s.persistence;
    frequency *= s.lacunarity;
  }
  return sum * normalisation(s);
}

float fractal(const PerlinNoise& noise, const FractalSettings& s, float x, float y, float z)
{
  float sum = 0.0f, amplitude = 1.0f, frequency = 1.0f, weight = 1.0f;
  for (int o = 0; o < s.octaves; ++o)
  {
    const float n = noise.noise(x * frequency + kOctaveShiftX * o, y * frequency + kOctaveShiftY * o,
                                z * frequency + kOctaveShiftZ * o);
    sum += amplitude * octaveTerm(s, n, weight);
    amplitude *= s.persistence;
    frequency *= s.lacunarity;
  }
  return sum * normalisation(s);
}

void fractalRow(const PerlinNoise& noise, const FractalSettings& s, float x0, float dx, float y, int n, float* out)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = 0.0f;
  }
  if (s.type == FractalType::Ridged)
  {
    // The weight chains octave to octave per sample: sample by sample.
    for (int i = 0; i < n; ++i)
    {
      out[i] = fractal(noise, s, x0 + dx * static_cast<float>(i), y);
    }
    return;
  }
  const bool absolute = s.type == FractalType::Turbulence;
  float amplitude = normalisation(s), frequency = 1.0f;
  for (int o = 0; o < s.octaves; ++o)
  {
    const float yo = y * frequency + kOctaveShiftY * o, xo = kOctaveShiftX * o;
    // Two loops rather than a test inside one: a branch in the loop stops vectorisation.
    if (absolute)
    {
      for (int i = 0; i < n; ++i)
      {
        out[i] += amplitude * std::fabs(noise.noise((x0 + dx * static_cast<float>(i)) * frequency + xo, yo));
      }
    }
    else
    {
      for (int i = 0; i < n; ++i)
      {
        out[i] += amplitude * noise.noise((x0 + dx * static_cast<float>(i)) * frequency + xo, yo);
      }
    }
    amplitude *= s.persistence;
    frequency *= s.lacunarity;
  }
}
} // namespace parafluid::terrain
