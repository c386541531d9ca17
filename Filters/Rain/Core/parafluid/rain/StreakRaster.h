#pragma once
// Rain streaks drawn on the CPU: the streak of the Rain representation's GPU pass
// (Representations/Rain/RainStreakVS.glsl and RainStreakFS.glsl: the segment a drop travels during
// the exposure, widened to its projected diameter and capped by half a width at each end, soft
// across, faded at the ends, coloured by the drop's radiance toward the eye), rasterised here and
// blended in the drops' order, so that a software OpenGL (Mesa's llvmpipe, pvbatch on a node
// without a GPU) draws one textured quad instead of a triangle per drop. Under llvmpipe a drop's
// triangle costs about half a microsecond of setup whatever it covers (Testing/Benchmarks/README.md,
// "Rain"), while the one to three pixels of a typical streak cost a few nanoseconds here.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace parafluid::rain
{
/// The camera of a frame, as the GPU pass gets it.
struct StreakCamera
{
  std::array<float, 16> worldToView{}; // row-major: view = M (x, y, z, 1)
  std::array<float, 16> viewToClip{};  // row-major: clip = P view
  int width = 1, height = 1;           // the viewport [pixels]
  std::array<float, 3> eye{};          // camera position, world [m]
};

/// How the streaks look (the Rain representation's properties of the same names).
struct StreakLook
{
  float widthScale = 1.0f;  // streak width over the drop's diameter
  float brightness = 1.0f;  // multiplies the radiance
  float opacity = 0.6f;     // of a streak's core
  float fogDistance = 0.0f; // [m]; 0: no fog
  float maxArea = 1e30f;    // the most pixels one streak may cover (its width shrinks to keep to it)
};

/// The pixels one of `drops` streaks may cover so that all of them together cover at most
/// kStreakScreens views of `pixels`: the frame's cost stays bounded whatever WidthScale says.
constexpr float kStreakScreens = 16.0f;
inline float streakAreaLimit(double pixels, std::size_t drops)
{
  return static_cast<float>(kStreakScreens * pixels / static_cast<double>(drops > 0 ? drops : 1));
}

/// The half width [px] a streak of `lengthPx` keeps to cover at most `maxArea` pixels (its
/// rectangle (length + 2 w) x 2 w), never under half a pixel.
inline float limitedHalfWidth(float halfWidth, float lengthPx, float maxArea)
{
  const float limit = 0.25f * (std::sqrt(lengthPx * lengthPx + 4.0f * maxArea) - lengthPx);
  return std::min(halfWidth, std::max(limit, 0.5f));
}

/// The drop's radiance toward each view direction: `columns` azimuths (from +x, counter-clockwise
/// about +z) by `rows` heights (view z from -1 to 1), RGBA floats, row-major (RainStreakPass's
/// texture).
struct RadianceTable
{
  const float* texels = nullptr;
  int columns = 0, rows = 0;
};

class StreakRaster
{
public:
  /// Blends the drops (8 floats each: x, y, z, diameter, vx, vy, vz, streak_length), in order,
  /// over a scene of window depth `depth` (width x height values in 0..1, row 0 at the bottom;
  /// null: nothing in front), as GL_LEQUAL depth tests and SRC_ALPHA / ONE_MINUS_SRC_ALPHA
  /// blending would. `rgba` (4 floats per pixel, resized here) gets what the drops add: the
  /// premultiplied colour and the coverage a, so the scene S becomes rgba.rgb + (1 - a) S.
  /// The result does not depend on `threads`. Returns the number of streaks drawn.
  std::size_t draw(const float* drops, std::size_t count, const StreakCamera& camera, const StreakLook& look,
                   const RadianceTable& radiance, const float* depth, std::vector<float>& rgba, int threads);

  /// A drawn streak in pixels (viewport centre at 0): what the GPU pass's vertex shader computes.
  struct Streak
  {
    float tail[2];      // the segment's tail end
    float direction[2]; // unit, tail to head
    float halfWidth;    // [pixels], at least half a pixel
    float total;        // length plus both caps [pixels]
    float depth;        // window depth of the streak (its head's)
    float colour[3];    // radiance toward the eye, times brightness, clamped to 0..1
    float peakAlpha;    // opacity x coverage of a thin drop x fog
    int rows[2];        // the pixel rows it may touch, inclusive
    int columns[2];     // the pixel columns it may touch, inclusive
  };
  /// The streak of one drop, or false where the GPU pass draws nothing (behind the eye, beyond the
  /// far plane, off screen, fainter than 1/512).
  static bool project(const float* drop, const StreakCamera& camera, const StreakLook& look,
                      const RadianceTable& radiance, Streak& out);

private:
  // Per thread, per screen tile: the streaks that may touch the tile, in the drops' order.
  std::vector<std::vector<std::vector<Streak>>> Buckets;
};
} // namespace parafluid::rain
