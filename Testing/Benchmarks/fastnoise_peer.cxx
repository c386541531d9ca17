// Peer comparison of the terrain noise (issue 22): FastNoise Lite (Auburn, MIT; one header) and,
// when built with PARAFLUID_WITH_FASTNOISE2, FastNoise2 (Auburn, MIT; SIMD, run-time dispatch)
// against ParaFluid's fractalRow: same process, same grid (1024^2), same 8 octaves of 2-D Perlin
// fBm (lacunarity 2, gain 0.5), rows split over OpenMP threads the same way. Prints samples/s of
// each, and single-octave Perlin samples/s. The peers are fetched and built by
// fastnoise_peer.sh, outside the CMake build.
#include "FastNoiseLite.h"
#ifdef PARAFLUID_WITH_FASTNOISE2
#include <FastNoise/FastNoise.h>
#endif
#include "parafluid/terrain/FractalNoise.h"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
template<class Fill>
double samplesPerSecond(int n, Fill fill)
{
  std::vector<float> field(static_cast<std::size_t>(n) * n);
  double best = 1e30;
  for (int repeat = 0; repeat < 5; ++repeat)
  {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (int j = 0; j < n; ++j)
    {
      fill(j, field.data() + static_cast<std::size_t>(j) * n);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = seconds < best ? seconds : best;
  }
  volatile float sink = field[12345];
  (void)sink;
  return static_cast<double>(n) * n / best;
}
} // namespace

int main(int argc, char** argv)
{
  const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
  omp_set_num_threads(threads);
  const int n = 1024;
  for (const int octaves : { 1, 8 })
  {
    FastNoiseLite peer(1337);
    peer.SetNoiseType(FastNoiseLite::NoiseType_Perlin);
    peer.SetFrequency(1.0f / 512.0f);
    peer.SetFractalType(octaves > 1 ? FastNoiseLite::FractalType_FBm : FastNoiseLite::FractalType_None);
    peer.SetFractalOctaves(octaves);
    peer.SetFractalLacunarity(2.0f);
    peer.SetFractalGain(0.5f);
    const double theirs = samplesPerSecond(n,
                                           [&](int j, float* row)
                                           {
                                             for (int i = 0; i < n; ++i)
                                             {
                                               row[i] = peer.GetNoise(static_cast<float>(i), static_cast<float>(j));
                                             }
                                           });
    const parafluid::terrain::PerlinNoise noise(1337);
    parafluid::terrain::FractalSettings s;
    s.octaves = octaves;
    const double ours = samplesPerSecond(
      n, [&](int j, float* row)
      { parafluid::terrain::fractalRow(noise, s, 0.0f, 1.0f / 512.0f, static_cast<float>(j) / 512.0f, n, row); });
    std::printf("%d octave(s), %d thread(s), 1024^2: ParaFluid %.1f M samples/s, FastNoise Lite %.1f M samples/s "
                "(ratio %.2f)\n",
                octaves, threads, ours / 1e6, theirs / 1e6, ours / theirs);
#ifdef PARAFLUID_WITH_FASTNOISE2
    // Its widest instruction set on this CPU, and AVX2 (the set of its published figure; ours).
    for (const FastSIMD::FeatureSet set : { FastSIMD::FeatureSet::Max, FastSIMD::FeatureSet::AVX2 })
    {
      auto perlin = FastNoise::New<FastNoise::Perlin>(set);
      FastNoise::SmartNode<FastNoise::Generator> generator = perlin;
      if (octaves > 1)
      {
        auto fbm = FastNoise::New<FastNoise::FractalFBm>(set);
        fbm->SetSource(perlin);
        fbm->SetOctaveCount(octaves);
        fbm->SetGain(0.5f);
        fbm->SetLacunarity(2.0f);
        generator = fbm;
      }
      const double simd = samplesPerSecond(n,
                                           [&](int j, float* row) {
                                             generator->GenUniformGrid2D(row, 0.0f, static_cast<float>(j) / 512.0f, n,
                                                                         1, 1.0f / 512.0f, 1.0f / 512.0f, 1337);
                                           });
      std::printf("%d octave(s), %d thread(s), 1024^2: FastNoise2 (%s) %.1f M samples/s (ParaFluid / FastNoise2 "
                  "%.2f)\n",
                  octaves, threads, FastSIMD::GetFeatureSetString(generator->GetActiveFeatureSet()), simd / 1e6,
                  ours / simd);
    }
#endif
  }
  return 0;
}
