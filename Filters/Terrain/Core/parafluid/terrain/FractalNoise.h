#pragma once
// Fractal sums of gradient noise over octaves: octave o samples the noise at frequency
// f0 * lacunarity^o with amplitude persistence^o (the gain). With persistence = lacunarity^-H the
// sum is a fractional Brownian surface of Hurst exponent H: its power spectrum falls as
// k^(-2H - 1) along a line (Musgrave, in Ebert et al., "Texturing and Modeling", 3rd ed., ch. 16).
#include "parafluid/terrain/PerlinNoise.h"

namespace parafluid::terrain
{
enum class FractalType
{
  FBm = 0,        // sum of noise
  Turbulence = 1, // sum of |noise|: creases at the zero lines (Perlin 1985)
  Ridged = 2      // Musgrave's ridged multifractal: (offset - |noise|)^2, each octave weighted by the last
};

struct FractalSettings
{
  FractalType type = FractalType::FBm;
  int octaves = 8;
  float lacunarity = 2.0f;  // frequency ratio between octaves
  float persistence = 0.5f; // amplitude ratio between octaves (the gain)
  float ridgeOffset = 1.0f; // ridged: the crest value; ridgeGain weighs an octave by the last
  float ridgeGain = 2.0f;
};

/// The fractal sum at (x, y) in units of the first octave's wavelength, normalised by the sum of
/// the octaves' amplitudes: FBm lies in [-1, 1], Turbulence and Ridged in [0, 1]. Each octave
/// is offset by a fixed irrational shift so lattice zeros of the octaves do not line up.
float fractal(const PerlinNoise& noise, const FractalSettings& settings, float x, float y);
/// The same in 3-D (clouds, volumes); FBm in [-kBound3D, kBound3D].
float fractal(const PerlinNoise& noise, const FractalSettings& settings, float x, float y, float z);

/// n samples at (x[i], y[i]): fractal() one by one (equal up to float rounding), evaluated octave
/// by octave over all points (PerlinNoise::accumulate: 8 at a time on AVX2 CPUs).
void fractalPoints(const PerlinNoise& noise, const FractalSettings& settings, const float* x, const float* y, int n,
                   float* out);

/// A row of n samples at (x0 + i dx, y): fractal() one by one (equal up to float rounding), octave by
/// octave over the row so the compiler can keep the inner loop tight.
void fractalRow(const PerlinNoise& noise, const FractalSettings& settings, float x0, float dx, float y, int n,
                float* out);
} // namespace parafluid::terrain
