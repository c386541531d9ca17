// Peer comparison of the terrain noise (issue 22): FastNoise Lite (Auburn, MIT; header fetched by
// fastnoise_peer.sh, not part of the build) against ParaFluid's fractalRow, same process, same
// grid (1024^2), same 8 octaves of 2-D Perlin fBm (lacunarity 2, gain 0.5), rows split over
// OpenMP threads the same way. Prints samples/s of both, and single-octave Perlin samples/s.
#include "FastNoiseLite.h"
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
  }
  return 0;
}
