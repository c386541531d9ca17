#include "parafluid/terrain/FractalNoise.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

void fractalPoints(const PerlinNoise& noise, const FractalSettings& s, const float* x, const float* y, int n,
                   float* out)
{
  // Per-thread scratch: rows are evaluated by many threads, each reusing its own buffers.
  thread_local std::vector<float> xo, yo, raw, weight;
  xo.resize(static_cast<std::size_t>(n)), yo.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    out[i] = 0.0f;
  }
  if (s.type == FractalType::Ridged)
  {
    // |noise| of each octave over all points, then the ridge and the weight that chains one
    // octave to the next, point by point (the same arithmetic as fractal()).
    weight.assign(static_cast<std::size_t>(n), 1.0f);
    float amplitude = 1.0f, frequency = 1.0f;
    for (int o = 0; o < s.octaves; ++o)
    {
      for (int i = 0; i < n; ++i)
      {
        xo[static_cast<std::size_t>(i)] = x[i] * frequency + kOctaveShiftX * o;
        yo[static_cast<std::size_t>(i)] = y[i] * frequency + kOctaveShiftY * o;
      }
      raw.assign(static_cast<std::size_t>(n), 0.0f);
      noise.accumulate(xo.data(), yo.data(), n, 1.0f, true, raw.data());
      for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
      {
        float signal = s.ridgeOffset - raw[i];
        signal *= signal * weight[i];
        weight[i] = std::min(1.0f, std::max(0.0f, signal * s.ridgeGain));
        out[i] += amplitude * signal;
      }
      amplitude *= s.persistence;
      frequency *= s.lacunarity;
    }
    const float scale = normalisation(s);
    for (int i = 0; i < n; ++i)
    {
      out[i] *= scale;
    }
    return;
  }
  const bool absolute = s.type == FractalType::Turbulence;
  float amplitude = normalisation(s), frequency = 1.0f;
  for (int o = 0; o < s.octaves; ++o)
  {
    for (int i = 0; i < n; ++i)
    {
      xo[static_cast<std::size_t>(i)] = x[i] * frequency + kOctaveShiftX * o;
      yo[static_cast<std::size_t>(i)] = y[i] * frequency + kOctaveShiftY * o;
    }
    noise.accumulate(xo.data(), yo.data(), n, amplitude, absolute, out);
    amplitude *= s.persistence;
    frequency *= s.lacunarity;
  }
}

void fractalRow(const PerlinNoise& noise, const FractalSettings& s, float x0, float dx, float y, int n, float* out)
{
  thread_local std::vector<float> xs, ys;
  xs.resize(static_cast<std::size_t>(n));
  ys.assign(static_cast<std::size_t>(n), y);
  for (int i = 0; i < n; ++i)
  {
    xs[static_cast<std::size_t>(i)] = x0 + dx * static_cast<float>(i);
  }
  fractalPoints(noise, s, xs.data(), ys.data(), n, out);
}
} // namespace parafluid::terrain
