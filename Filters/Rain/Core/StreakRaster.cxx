#include "parafluid/rain/StreakRaster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace parafluid::rain
{
namespace
{
constexpr float kTwoPi = 6.28318530718f;
constexpr float kFaintest = 1.0f / 512.0f; // below half a level of an 8-bit channel: not drawn
constexpr float kNearZ = -1e-3f;           // [m] in view space: streaks are cut 1 mm in front of the eye
constexpr int kTile = 64;                  // [pixels]: a tile's colour and depth, 80 kB, stay in cache

/// y = M (x, 1) for a row-major 4 x 4 M.
void transform(const std::array<float, 16>& m, const float x[4], float y[4])
{
  for (int r = 0; r < 4; ++r)
  {
    y[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3] * x[3];
  }
}

float smoothstep(float edge, float t)
{
  const float s = std::clamp(t / edge, 0.0f, 1.0f);
  return s * s * (3.0f - 2.0f * s);
}

/// exp(-2 y^2) for |y| <= 1 from a table in y^2 (linear between 256 intervals: within 2e-6), the
/// streak's profile across.
class AcrossProfile
{
public:
  AcrossProfile()
  {
    for (int k = 0; k <= kIntervals; ++k)
    {
      this->Table[k] = std::exp(-2.0f * static_cast<float>(k) / kIntervals);
    }
  }
  float operator()(float y2) const
  {
    const float at = std::min(y2, 1.0f) * kIntervals;
    const int k = std::min(static_cast<int>(at), kIntervals - 1);
    const float f = at - static_cast<float>(k);
    return this->Table[k] + f * (this->Table[k + 1] - this->Table[k]);
  }

private:
  static constexpr int kIntervals = 256;
  float Table[kIntervals + 1];
};

/// atan2(y, x) in [-pi, pi] within 1e-5 rad (a minimax polynomial in the octant's ratio): the
/// library's call was a tenth of the streaks' time, for a column of the radiance table 2.8
/// degrees wide.
float fastAtan2(float y, float x)
{
  const float ax = std::fabs(x), ay = std::fabs(y);
  const float big = std::max(ax, ay), small = std::min(ax, ay);
  const float a = big > 0.0f ? small / big : 0.0f;
  const float s = a * a;
  float r = ((-0.0464964749f * s + 0.15931422f) * s - 0.327622764f) * s * a + a;
  r = ay > ax ? 1.57079637f - r : r;
  r = x < 0.0f ? 3.14159274f - r : r;
  return y < 0.0f ? -r : r;
}

void radianceToward(const RadianceTable& table, float vx, float vy, float vz, float out[3])
{
  const float length = std::sqrt(vx * vx + vy * vy + vz * vz);
  if (!table.texels || table.columns <= 0 || table.rows <= 0 || !(length > 0.0f))
  {
    out[0] = out[1] = out[2] = 0.0f;
    return;
  }
  float azimuth = fastAtan2(vy, vx);
  azimuth = azimuth < 0.0f ? azimuth + kTwoPi : azimuth;
  const int column = static_cast<int>(azimuth / kTwoPi * static_cast<float>(table.columns)) % table.columns;
  const int row =
    std::clamp(static_cast<int>((vz / length + 1.0f) * 0.5f * static_cast<float>(table.rows)), 0, table.rows - 1);
  const float* texel = table.texels + 4 * (static_cast<std::size_t>(row) * table.columns + column);
  out[0] = texel[0];
  out[1] = texel[1];
  out[2] = texel[2];
}

/// Blends one streak into the pixels of the image inside `rect` (first and last column, first and
/// last row).
void drawInside(const StreakRaster::Streak& s, const float* depth, int width, int height, const int rect[4],
                const AcrossProfile& across, float* rgba)
{
  const int columnLow = std::max(s.columns[0], rect[0]), columnHigh = std::min(s.columns[1], rect[1]);
  const int rowLow = std::max(s.rows[0], rect[2]), rowHigh = std::min(s.rows[1], rect[3]);
  const float normal[2] = { -s.direction[1], s.direction[0] };
  const float inverseHalfWidth = 1.0f / s.halfWidth, inverseTotal = 1.0f / s.total;
  const float capEdge = 2.0f * s.halfWidth * inverseTotal; // the ends fade over twice a cap's share
  for (int j = rowLow; j <= rowHigh; ++j)
  {
    const float ry = static_cast<float>(j) + 0.5f - 0.5f * static_cast<float>(height) - s.tail[1];
    for (int i = columnLow; i <= columnHigh; ++i)
    {
      const float rx = static_cast<float>(i) + 0.5f - 0.5f * static_cast<float>(width) - s.tail[0];
      const float x = (rx * s.direction[0] + ry * s.direction[1] + s.halfWidth) * inverseTotal;
      const float y = (rx * normal[0] + ry * normal[1]) * inverseHalfWidth;
      if (x < 0.0f || x > 1.0f || std::fabs(y) > 1.0f)
      {
        continue;
      }
      const std::size_t pixel = static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + i;
      if (depth && !(s.depth <= depth[pixel]))
      {
        continue; // hidden by the scene (GL_LEQUAL)
      }
      const float ends = smoothstep(capEdge, x) * smoothstep(capEdge, 1.0f - x);
      const float alpha = std::clamp(s.peakAlpha * across(y * y) * ends, 0.0f, 1.0f);
      if (alpha < kFaintest)
      {
        continue;
      }
      float* p = rgba + 4 * pixel;
      for (int c = 0; c < 3; ++c)
      {
        p[c] = alpha * s.colour[c] + (1.0f - alpha) * p[c];
      }
      p[3] = alpha + (1.0f - alpha) * p[3];
    }
  }
}
} // namespace

bool StreakRaster::project(const float* drop, const StreakCamera& camera, const StreakLook& look,
                           const RadianceTable& radiance, Streak& out)
{
  const float* head = drop;
  const float diameter = drop[3];
  const float* velocity = drop + 4;
  const float speed = std::sqrt(velocity[0] * velocity[0] + velocity[1] * velocity[1] + velocity[2] * velocity[2]);
  float along[3] = { 0.0f, 0.0f, -1.0f };
  if (speed > 0.0f)
  {
    for (int k = 0; k < 3; ++k)
    {
      along[k] = velocity[k] / speed;
    }
  }
  const float headWorld[4] = { head[0], head[1], head[2], 1.0f };
  const float tailWorld[4] = { head[0] - along[0] * drop[7], head[1] - along[1] * drop[7], head[2] - along[2] * drop[7],
                               1.0f };
  float headView[4], tailView[4];
  transform(camera.worldToView, headWorld, headView);
  transform(camera.worldToView, tailWorld, tailView);
  if (headView[2] > kNearZ && tailView[2] > kNearZ)
  {
    return false; // wholly behind the eye
  }
  // A streak partly behind the eye is cut at the near distance.
  if (headView[2] > kNearZ)
  {
    const float f = (tailView[2] - kNearZ) / (tailView[2] - headView[2]);
    for (int k = 0; k < 4; ++k)
    {
      headView[k] = tailView[k] + f * (headView[k] - tailView[k]);
    }
  }
  if (tailView[2] > kNearZ)
  {
    const float f = (headView[2] - kNearZ) / (headView[2] - tailView[2]);
    for (int k = 0; k < 4; ++k)
    {
      tailView[k] = headView[k] + f * (tailView[k] - headView[k]);
    }
  }
  float headClip[4], tailClip[4];
  transform(camera.viewToClip, headView, headClip);
  transform(camera.viewToClip, tailView, tailClip);
  const float headDepth = headClip[2] / headClip[3];
  if (headDepth > 1.0f)
  {
    return false; // beyond the far plane
  }
  const float halfViewport[2] = { 0.5f * static_cast<float>(camera.width), 0.5f * static_cast<float>(camera.height) };
  const float headPx[2] = { headClip[0] / headClip[3] * halfViewport[0], headClip[1] / headClip[3] * halfViewport[1] };
  const float tailPx[2] = { tailClip[0] / tailClip[3] * halfViewport[0], tailClip[1] / tailClip[3] * halfViewport[1] };
  float direction[2] = { headPx[0] - tailPx[0], headPx[1] - tailPx[1] };
  const float lengthPx = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1]);
  if (lengthPx > 1e-3f)
  {
    direction[0] /= lengthPx;
    direction[1] /= lengthPx;
  }
  else
  {
    direction[0] = 0.0f;
    direction[1] = 1.0f;
  }
  // Projected diameter at the drop (perspective: P11 D / depth, times half the viewport height).
  const float viewDepth = std::max(-headView[2], 1e-3f);
  const float diameterPx = look.widthScale * diameter * camera.viewToClip[5] / viewDepth * halfViewport[1];
  const float halfWidth = limitedHalfWidth(0.5f * std::max(diameterPx, 1.0f), lengthPx, look.maxArea);
  float fog = 1.0f;
  if (look.fogDistance > 0.0f)
  {
    const float d[3] = { head[0] - camera.eye[0], head[1] - camera.eye[1], head[2] - camera.eye[2] };
    fog = std::exp(-std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / look.fogDistance);
  }
  const float peakAlpha = look.opacity * std::min(diameterPx, 1.0f) * fog;
  if (!std::isfinite(headPx[0] + headPx[1] + tailPx[0] + tailPx[1] + halfWidth + headDepth))
  {
    return false; // a degenerate camera (the GPU would draw nothing sensible either)
  }
  for (int a = 0; a < 2; ++a)
  {
    const float low = std::min(headPx[a], tailPx[a]) - halfWidth, high = std::max(headPx[a], tailPx[a]) + halfWidth;
    if (low > halfViewport[a] || high < -halfViewport[a])
    {
      return false; // off screen
    }
  }
  if (!(peakAlpha >= kFaintest))
  {
    return false;
  }
  out.tail[0] = tailPx[0];
  out.tail[1] = tailPx[1];
  out.direction[0] = direction[0];
  out.direction[1] = direction[1];
  out.halfWidth = halfWidth;
  out.total = lengthPx + 2.0f * halfWidth;
  out.depth = 0.5f * std::max(headDepth, -1.0f) + 0.5f;
  float colour[3];
  radianceToward(radiance, head[0] - camera.eye[0], head[1] - camera.eye[1], head[2] - camera.eye[2], colour);
  for (int c = 0; c < 3; ++c)
  {
    // A fixed-point framebuffer takes the source colour clamped to 0..1.
    out.colour[c] = std::clamp(look.brightness * colour[c], 0.0f, 1.0f);
  }
  out.peakAlpha = peakAlpha;
  // The pixels whose centres the capsule's rectangle may cover: the box of its four corners.
  const float normal[2] = { -direction[1], direction[0] };
  float low[2] = { 1e30f, 1e30f }, high[2] = { -1e30f, -1e30f };
  for (const float u : { -halfWidth, lengthPx + halfWidth })
  {
    for (const float v : { -halfWidth, halfWidth })
    {
      for (int a = 0; a < 2; ++a)
      {
        const float corner = tailPx[a] + direction[a] * u + normal[a] * v;
        low[a] = std::min(low[a], corner);
        high[a] = std::max(high[a], corner);
      }
    }
  }
  // Pixel k's centre is at k + 0.5 - half the viewport.
  const int size[2] = { camera.width, camera.height };
  int first[2], last[2];
  for (int a = 0; a < 2; ++a)
  {
    first[a] = static_cast<int>(std::ceil(std::max(low[a] + halfViewport[a] - 0.5f, -1.0f)));
    last[a] = static_cast<int>(std::floor(std::min(high[a] + halfViewport[a] - 0.5f, static_cast<float>(size[a]))));
    first[a] = std::max(first[a], 0);
    last[a] = std::min(last[a], size[a] - 1);
  }
  out.columns[0] = first[0];
  out.columns[1] = last[0];
  out.rows[0] = first[1];
  out.rows[1] = last[1];
  return first[0] <= last[0] && first[1] <= last[1];
}

std::size_t StreakRaster::draw(const float* drops, std::size_t count, const StreakCamera& camera,
                               const StreakLook& look, const RadianceTable& radiance, const float* depth,
                               std::vector<float>& rgba, int threads)
{
  const int width = std::max(camera.width, 1), height = std::max(camera.height, 1);
  rgba.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  threads = std::max(threads, 1);
  // The image is drawn tile by tile, each tile's streaks kept together, so that both the tile's
  // pixels and its streaks stay in cache: drawn over the whole image in the drops' order, each
  // streak's few pixels were cache misses in a 15 MB image, and read through a list of pointers
  // per tile, each streak was one.
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  const auto tiles = static_cast<std::size_t>(tilesX) * static_cast<std::size_t>(tilesY);
  this->Buckets.resize(static_cast<std::size_t>(threads));
  for (auto& perThread : this->Buckets)
  {
    perThread.resize(tiles);
    for (auto& bucket : perThread)
    {
      bucket.clear(); // keeps its capacity for the next frame; a team smaller than asked leaves some empty
    }
  }
  std::vector<std::size_t> projected(static_cast<std::size_t>(threads), 0);
  const auto n = static_cast<std::int64_t>(count);
  // Each thread projects a contiguous range of drops, in order, into its buckets (one per tile the
  // streak may touch). A tile then blends thread 0's bucket, thread 1's, and so on: the drops'
  // order, so a pixel's result does not depend on the thread count.
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    const int t = omp_get_thread_num();
    const int team = omp_get_num_threads();
#else
    const int t = 0;
    const int team = 1;
#endif
    std::vector<std::vector<Streak>>& mine = this->Buckets[static_cast<std::size_t>(t)];
    const std::int64_t begin = n * t / team, end = n * (t + 1) / team;
    Streak s;
    std::size_t drawn = 0;
    for (std::int64_t k = begin; k < end; ++k)
    {
      if (!project(drops + 8 * k, camera, look, radiance, s))
      {
        continue;
      }
      ++drawn;
      for (int ty = s.rows[0] / kTile; ty <= s.rows[1] / kTile; ++ty)
      {
        for (int tx = s.columns[0] / kTile; tx <= s.columns[1] / kTile; ++tx)
        {
          mine[static_cast<std::size_t>(ty) * tilesX + tx].push_back(s);
        }
      }
    }
    projected[static_cast<std::size_t>(t)] = drawn;
#pragma omp barrier
    static const AcrossProfile across;
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t tile = 0; tile < static_cast<std::int64_t>(tiles); ++tile)
    {
      const int tx = static_cast<int>(tile % tilesX), ty = static_cast<int>(tile / tilesX);
      const int rect[4] = { tx * kTile, std::min(tx * kTile + kTile, width) - 1, ty * kTile,
                            std::min(ty * kTile + kTile, height) - 1 };
      for (int j = rect[2]; j <= rect[3]; ++j)
      {
        float* row = rgba.data() + 4 * (static_cast<std::size_t>(j) * width + rect[0]);
        std::fill(row, row + 4 * (rect[1] - rect[0] + 1), 0.0f);
      }
      for (int owner = 0; owner < team; ++owner)
      {
        for (const Streak& streak : this->Buckets[static_cast<std::size_t>(owner)][static_cast<std::size_t>(tile)])
        {
          drawInside(streak, depth, width, height, rect, across, rgba.data());
        }
      }
    }
  }
  std::size_t drawn = 0;
  for (const std::size_t k : projected)
  {
    drawn += k;
  }
  return drawn;
}
} // namespace parafluid::rain
