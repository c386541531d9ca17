// Foam particles: nothing inside a ball is flagged, the apex of a sharp crest is, spray is, and
// the hysteresis never switches a particle that is a candidate for fewer than PersistFrames frames.
#include "parafluid/npr/FoamClassifier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace parafluid::npr;

namespace
{
constexpr double kSpacing = 0.01; // d [m]

FoamParameters parameters()
{
  FoamParameters p;
  p.kernelRadius = 3 * kSpacing; // the Foam Particles filter's default
  p.particleVolume = kSpacing * kSpacing * kSpacing;
  return p;
}
} // namespace

TEST(FoamClassifier, NothingInsideABallIsFlagged)
{
  // Jittered lattice ball of radius 10 d: a gently curved surface (radius 3.3 h), though its
  // lattice terraces give crest potentials up to 0.44.
  const double radius = 10 * kSpacing;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1 * kSpacing, 0.1 * kSpacing);
  std::vector<float> xyz;
  for (int k = -10; k <= 10; ++k)
    for (int j = -10; j <= 10; ++j)
      for (int i = -10; i <= 10; ++i)
        if ((i * i + j * j + k * k) * kSpacing * kSpacing <= radius * radius)
          xyz.insert(xyz.end(),
                     { float(i * kSpacing + u(rng)), float(j * kSpacing + u(rng)), float(k * kSpacing + u(rng)) });
  const std::size_t n = xyz.size() / 3;
  const FoamScores scores = scoreFoam(xyz.data(), n, parameters());
  std::size_t interior = 0, interiorSurface = 0, flagged = 0, surface = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double r =
      std::sqrt(xyz[3 * i] * xyz[3 * i] + xyz[3 * i + 1] * xyz[3 * i + 1] + xyz[3 * i + 2] * xyz[3 * i + 2]);
    surface += scores.surface[i];
    flagged += scores.candidate[i];
    if (r < radius - 2 * kSpacing)
    {
      ++interior;
      interiorSurface += scores.surface[i];
      EXPECT_EQ(scores.candidate[i], 0) << "interior particle at r = " << r / kSpacing << " d";
    }
  }
  float maxCrest = 0.0f;
  for (float c : scores.crest)
  {
    maxCrest = std::max(maxCrest, c);
  }
  std::printf("ball: %zu particles, %zu interior, %zu surface, %zu flagged, largest crest potential %.3f\n", n,
              interior, surface, flagged, maxCrest);
  EXPECT_GT(interior, 1000u);
  EXPECT_EQ(interiorSurface, 0u);
  EXPECT_GT(surface, 500u); // the shell is found
  EXPECT_EQ(flagged, 0u);   // and a smooth ball has no crest
}

TEST(FoamClassifier, TheApexOfASharpCrestIsFlaggedAndItsFlanksAreNot)
{
  // A long ridge with 45-degree flanks (apex crest potential about 1.2): z <= 20 d - |x|, over a base 8 d deep, 60 d
  // long in y.
  std::vector<float> xyz;
  for (int j = 0; j < 60; ++j)
    for (int i = -30; i <= 30; ++i)
      for (int k = -8; k <= 20 - std::abs(i); ++k)
        xyz.insert(xyz.end(), { float(i * kSpacing), float(j * kSpacing), float(k * kSpacing) });
  const std::size_t n = xyz.size() / 3;
  const FoamScores scores = scoreFoam(xyz.data(), n, parameters());
  std::size_t apex = 0, apexFlagged = 0, flank = 0, flankFlagged = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x = xyz[3 * i] / kSpacing, y = xyz[3 * i + 1] / kSpacing, z = xyz[3 * i + 2] / kSpacing;
    if (y < 10 || y > 49)
    {
      continue; // away from the ridge's ends, which are convex edges of their own
    }
    const double height = 20 - std::abs(x) - z; // depth below the surface, in d
    if (std::abs(x) <= 1 && height < 0.5)
    {
      ++apex;
      apexFlagged += scores.candidate[i];
    }
    else if (std::abs(x) >= 6 && std::abs(x) <= 14 && height < 0.5)
    {
      ++flank;
      flankFlagged += scores.candidate[i];
      EXPECT_EQ(scores.surface[i], 1) << "flank particle not on the surface";
    }
    else if (height > 4 && z > -4) // more than 4 d from the top and from the base's own edges
    {
      EXPECT_EQ(scores.candidate[i], 0) << "inside the crest";
    }
  }
  std::printf("crest: apex %zu/%zu flagged, flanks %zu/%zu flagged\n", apexFlagged, apex, flankFlagged, flank);
  EXPECT_EQ(apexFlagged, apex);
  EXPECT_EQ(flankFlagged, 0u);
}

TEST(FoamClassifier, IsolatedParticlesAreSpray)
{
  std::vector<float> xyz;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i)
        xyz.insert(xyz.end(), { float(i * kSpacing), float(j * kSpacing), float(k * kSpacing) });
  xyz.insert(xyz.end(), { 0.5f, 0.5f, 0.5f }); // a droplet far from the block
  const FoamScores scores = scoreFoam(xyz.data(), xyz.size() / 3, parameters());
  EXPECT_EQ(scores.candidate.back(), 1);
  EXPECT_FLOAT_EQ(scores.score.back(), 1.0f);
  EXPECT_EQ(scores.candidate[3 * 36 + 3 * 6 + 3], 0) << "a particle in the middle of the block";
}

TEST(FoamHysteresis, ShortCandidaciesNeverSwitch)
{
  FoamHysteresis hysteresis;
  const std::int64_t ids[3] = { 7, 11, 13 };
  // Particle 7: a candidate for 2 frames, then not (PersistFrames 3): never foam.
  // Particle 11: a candidate for 3 frames: foam from the third; then 2 frames not: still foam;
  //   the third: off.
  // Particle 13: alternating every frame: never foam.
  const std::uint8_t frames[8][3] = { { 1, 1, 1 }, { 1, 1, 0 }, { 0, 1, 1 }, { 0, 0, 0 },
                                      { 1, 0, 1 }, { 1, 0, 0 }, { 0, 1, 1 }, { 0, 0, 0 } };
  const std::uint8_t expected11[8] = { 0, 0, 1, 1, 1, 0, 0, 0 };
  std::vector<std::uint8_t> foam;
  for (int f = 0; f < 8; ++f)
  {
    hysteresis.update(ids, frames[f], 3, 3, foam);
    EXPECT_EQ(foam[0], 0) << "frame " << f;
    EXPECT_EQ(foam[1], expected11[f]) << "frame " << f;
    EXPECT_EQ(foam[2], 0) << "frame " << f;
  }
  // Ids are what counts, not positions in the arrays: reorder, and a particle keeps its state.
  FoamHysteresis byId;
  const std::uint8_t on[2] = { 1, 1 };
  const std::int64_t order1[2] = { 1, 2 }, order2[2] = { 2, 1 };
  const std::uint8_t mixed[2] = { 1, 0 }; // id 2 a candidate, id 1 not
  byId.update(order1, on, 2, 2, foam);
  byId.update(order2, mixed, 2, 2, foam);
  EXPECT_EQ(foam[0], 1); // id 2: two frames in a row
  EXPECT_EQ(foam[1], 0); // id 1: one frame only
  byId.reset();
  EXPECT_EQ(byId.trackedParticles(), 0u);
}

TEST(FoamClassifier, EmptyInputAndBadParameters)
{
  EXPECT_TRUE(scoreFoam(nullptr, 0, parameters()).score.empty());
  FoamParameters p = parameters();
  p.kernelRadius = 0;
  const float one[3] = { 0, 0, 0 };
  EXPECT_THROW(scoreFoam(one, 1, p), std::invalid_argument);
  p = parameters();
  p.crestThreshold = -1;
  EXPECT_THROW(scoreFoam(one, 1, p), std::invalid_argument);
  const float bad[3] = { 0, INFINITY, 0 };
  EXPECT_THROW(scoreFoam(bad, 1, parameters()), std::invalid_argument);
}

TEST(FoamClassifier, ReportsProgressInBlocksAndStopsWhenAsked)
{
  // A 50 x 50 x 30 slab: 75 000 particles, two blocks a pass.
  std::vector<float> xyz;
  for (int k = 0; k < 30; ++k)
    for (int j = 0; j < 50; ++j)
      for (int i = 0; i < 50; ++i)
        xyz.insert(xyz.end(), { float(i * kSpacing), float(j * kSpacing), float(k * kSpacing) });
  const std::size_t n = xyz.size() / 3;
  const FoamScores plain = scoreFoam(xyz.data(), n, parameters());
  std::vector<double> reported;
  const FoamScores blocked = scoreFoam(xyz.data(), n, parameters(),
                                       [&](double f)
                                       {
                                         reported.push_back(f);
                                         return true;
                                       });
  EXPECT_EQ(blocked.score, plain.score); // the blocks do not change a score
  ASSERT_EQ(reported.size(), 4u);
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_DOUBLE_EQ(reported.back(), 1.0);
  int calls = 0;
  const FoamScores stopped = scoreFoam(xyz.data(), n, parameters(),
                                       [&](double)
                                       {
                                         ++calls;
                                         return false;
                                       });
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(std::all_of(stopped.score.begin(), stopped.score.end(), [](float s) { return s == 0.0f; }));
}
