#include "parafluid/npr/BrushStrokes.h"
#include "parafluid/common/MathConstants.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace parafluid::npr
{
std::string validate(const BrushStrokeParameters& p)
{
  std::string problem = validate(p.flow);
  if (!problem.empty())
  {
    return problem;
  }
  std::ostringstream why;
  if (!(p.strokeLength > 0.0) || !std::isfinite(p.strokeLength))
  {
    why << "the stroke length must be a positive length (got " << p.strokeLength << ")";
  }
  else if (!(p.fillSpacing > 0.0) || !std::isfinite(p.fillSpacing))
  {
    why << "the fill spacing must be a positive length (got " << p.fillSpacing << ")";
  }
  else if (p.maxStrokes < 1)
  {
    why << "MaxStrokes must be at least 1";
  }
  return why.str();
}

namespace
{

struct FillCandidate
{
  std::uint32_t particle;
  float distance2; // to its cube's centre
};

/// A well-mixed 64-bit key of an integer cube index (also the seed of its rest direction).
std::uint64_t cubeKey(std::int64_t i, std::int64_t j, std::int64_t k)
{
  std::uint64_t h = static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(j) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(k) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
  return h;
}
} // namespace

BrushStrokeSet layoutBrushStrokes(const float* xyz, const float* velocity, const float* value, std::size_t n,
                                  const BrushStrokeParameters& p, const std::function<bool(double)>& progress)
{
  const std::string problem = validate(p);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  BrushStrokeSet out;
  out.offsets.push_back(0);
  if (n == 0)
  {
    return out;
  }
  // Flow strokes: from every seedStride-th fast particle (a slow one's line would be shorter than
  // a stroke and dropped), thinned evenly to twice the budget so that the work follows the
  // strokes drawn, not the particle count.
  const double slowSpeed = p.strokeLength / p.flow.lineDuration; // [m/s]
  auto speedOf = [&](std::size_t i)
  {
    const float* v = velocity + 3 * i;
    return std::sqrt(static_cast<double>(v[0]) * v[0] + static_cast<double>(v[1]) * v[1] +
                     static_cast<double>(v[2]) * v[2]);
  };
  std::vector<std::uint32_t> fast;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!(std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) && std::isfinite(xyz[3 * i + 2])))
    {
      throw std::invalid_argument("particle " + std::to_string(i) + " has a NaN or infinite position");
    }
    if (speedOf(i) >= slowSpeed)
    {
      fast.push_back(static_cast<std::uint32_t>(i));
    }
  }
  std::size_t stride = static_cast<std::size_t>(p.flow.seedStride);
  stride = std::max(stride, (fast.size() + 2 * p.maxStrokes - 1) / (2 * p.maxStrokes));
  std::vector<float> seeds;
  std::vector<std::uint32_t> seedParticle;
  for (std::size_t k = 0; k < fast.size(); k += stride)
  {
    seedParticle.push_back(fast[k]);
    seeds.insert(seeds.end(), xyz + 3 * fast[k], xyz + 3 * fast[k] + 3);
  }
  auto flowProgress = [&](double f) { return !progress || progress(0.9 * f); };
  FlowLineSet lines;
  if (!seedParticle.empty())
  {
    lines = traceFlowLines(xyz, velocity, n, p.flow, seeds.data(), seedParticle.size(), flowProgress);
  }
  if (progress && !progress(0.9))
  {
    return BrushStrokeSet{ {}, { 0 }, {}, {}, {} };
  }
  auto addStroke = [&](const float* first, std::size_t count, std::uint32_t seed, bool fixed)
  {
    out.points.insert(out.points.end(), first, first + 3 * count);
    out.offsets.push_back(static_cast<std::uint32_t>(out.points.size() / 3));
    out.value.push_back(value ? value[seed] : 0.0f);
    out.seed.push_back(seed);
    out.fixed.push_back(fixed ? 1 : 0);
  };
  for (std::size_t l = 0; l < lines.lineCount() && out.strokeCount() < p.maxStrokes; ++l)
  {
    if (lines.length[l] >= p.strokeLength)
    {
      addStroke(&lines.points[3 * lines.offsets[l]], lines.offsets[l + 1] - lines.offsets[l],
                seedParticle[lines.seed[l]], false);
    }
  }

  // Fixed strokes: per grid cube, the slow particle nearest its centre.
  const double inverse = 1.0 / p.fillSpacing;
  std::unordered_map<std::uint64_t, FillCandidate> cubes;
  std::vector<std::uint64_t> order; // cubes in the order first met, so the result is reproducible
  for (std::size_t i = 0; i < n; ++i)
  {
    if (speedOf(i) >= slowSpeed)
    {
      continue;
    }
    const float* x = xyz + 3 * i;
    std::int64_t c[3];
    float d2 = 0.0f;
    for (int a = 0; a < 3; ++a)
    {
      const double s = x[a] * inverse;
      c[a] = static_cast<std::int64_t>(std::floor(s));
      const double offset = (s - static_cast<double>(c[a]) - 0.5) * p.fillSpacing;
      d2 += static_cast<float>(offset * offset);
    }
    const std::uint64_t key = cubeKey(c[0], c[1], c[2]);
    auto [it, inserted] = cubes.try_emplace(key, FillCandidate{ static_cast<std::uint32_t>(i), d2 });
    if (inserted)
    {
      order.push_back(key);
    }
    else if (d2 < it->second.distance2)
    {
      it->second = FillCandidate{ static_cast<std::uint32_t>(i), d2 };
    }
  }
  for (std::size_t c = 0; c < order.size() && out.strokeCount() < p.maxStrokes; ++c)
  {
    const std::uint32_t i = cubes[order[c]].particle;
    const float* x = xyz + 3 * i;
    const float* v = velocity + 3 * i;
    double direction[3] = { v[0], v[1], v[2] };
    const double speed =
      std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
    if (speed > 1e-6 * slowSpeed)
    {
      for (double& d : direction)
      {
        d /= speed;
      }
    }
    else
    {
      const double angle = static_cast<double>(order[c] >> 11) * (2.0 * kPi / 9007199254740992.0); // top 53 bits / 2^53
      direction[0] = std::cos(angle);
      direction[1] = std::sin(angle);
      direction[2] = 0.0;
    }
    // Three points, so a fixed stroke has a middle like a flow stroke.
    float points[9];
    for (int k = 0; k < 3; ++k)
    {
      const double t = (0.5 * k - 0.5) * p.strokeLength;
      for (int a = 0; a < 3; ++a)
      {
        points[3 * k + a] = static_cast<float>(x[a] + t * direction[a]);
      }
    }
    addStroke(points, 3, i, true);
  }
  if (progress)
  {
    progress(1.0);
  }
  return out;
}
} // namespace parafluid::npr
