#pragma once
// The splash sprites, drawn by the project (no image database): three sequences of six frames of
// a drop hitting the ground, as soft discs of water in an RGBA atlas.
//  - flat: a crown (a rim of droplets rising from a ring and falling back) and a central jet;
//  - sloped: the crown leans and spreads downhill;
//  - steep: a directional splash, droplets thrown downhill like a small waterfall.
// The sprite's bottom edge is the ground, its up axis the surface normal, +x downhill.
#include <cstdint>
#include <vector>

namespace parafluid::rain
{
constexpr int kSplashSequences = 3;
constexpr int kSplashFrames = 6;

enum class SplashKind
{
  Flat = 0,
  Sloped = 1,
  Steep = 2
};

/// The sequence for a surface slope [deg] (water counts as flat): flat below 15, steep above 40.
SplashKind splashKindForSlope(double slopeDegrees, bool onWater);

/// The atlas: kSplashFrames columns by kSplashSequences rows of size x size texels, RGBA8, row 0
/// at the bottom (OpenGL's texture order); sequence s, frame f at column f, row s. Colour is white,
/// alpha the water's coverage.
std::vector<std::uint8_t> splashAtlas(int size);
} // namespace parafluid::rain
