#include "parafluid/npr/FlowLines.h"

#include "parafluid/common/ParticleNeighbourhood.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace parafluid::npr
{
namespace
{
/// Shepard-normalised poly6 interpolation of the velocity at p; false where no particle is within
/// the kernel's reach.
bool velocityAt(const ParticleNeighbourhood& near, const float* velocity, const float p[3], float v[3])
{
  const float h2 = near.radius() * near.radius();
  double weight = 0.0, sum[3] = { 0.0, 0.0, 0.0 };
  near.forEachNear(p,
                   [&](std::uint32_t j, float, float, float, float r2)
                   {
                     const double t = h2 - r2;
                     const double w = t * t * t; // the kernel's constant cancels in the normalisation
                     weight += w;
                     for (int a = 0; a < 3; ++a)
                     {
                       sum[a] += w * velocity[3 * j + a];
                     }
                   });
  if (!(weight > 0.0))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    v[a] = static_cast<float>(sum[a] / weight);
  }
  // A velocity that overflows float, or a NaN from the particles, ends the line here.
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

/// One step of length dt from x; false where the field is undefined along the way.
bool step(const ParticleNeighbourhood& near, const float* velocity, FlowIntegrator integrator, float dt,
          const float x[3], float next[3])
{
  float k1[3], k2[3], probe[3];
  if (!velocityAt(near, velocity, x, k1))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    probe[a] = x[a] + 0.5f * dt * k1[a];
  }
  if (!velocityAt(near, velocity, probe, k2))
  {
    return false;
  }
  if (integrator == FlowIntegrator::RK2)
  {
    for (int a = 0; a < 3; ++a)
    {
      next[a] = x[a] + dt * k2[a];
    }
    return true;
  }
  float k3[3], k4[3];
  for (int a = 0; a < 3; ++a)
  {
    probe[a] = x[a] + 0.5f * dt * k2[a];
  }
  if (!velocityAt(near, velocity, probe, k3))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    probe[a] = x[a] + dt * k3[a];
  }
  if (!velocityAt(near, velocity, probe, k4))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    next[a] = x[a] + dt / 6.0f * (k1[a] + 2.0f * k2[a] + 2.0f * k3[a] + k4[a]);
  }
  return true;
}

struct TracedLine
{
  std::vector<float> points, speed;
  double length = 0.0, turning = 0.0;
};

TracedLine trace(const ParticleNeighbourhood& near, const float* velocity, const FlowLineParameters& p,
                 const float start[3])
{
  TracedLine line;
  const float dt = static_cast<float>(p.lineDuration / (p.pointsPerLine - 1));
  float x[3] = { start[0], start[1], start[2] };
  for (int k = 0; k < p.pointsPerLine; ++k)
  {
    float v[3];
    if (!velocityAt(near, velocity, x, v))
    {
      break;
    }
    line.points.insert(line.points.end(), x, x + 3);
    line.speed.push_back(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    float next[3];
    if (k + 1 == p.pointsPerLine || !step(near, velocity, p.integrator, dt, x, next))
    {
      break;
    }
    std::copy(next, next + 3, x);
  }
  const std::size_t m = line.points.size() / 3;
  for (std::size_t k = 1; k < m; ++k)
  {
    const float* a = &line.points[3 * (k - 1)];
    const float* b = &line.points[3 * k];
    line.length += std::sqrt(double(b[0] - a[0]) * (b[0] - a[0]) + double(b[1] - a[1]) * (b[1] - a[1]) +
                             double(b[2] - a[2]) * (b[2] - a[2]));
  }
  return line;
}

/// Angle [rad] between steps a->b and b->c; 0 when either step has no length.
double turnAngle(const float* a, const float* b, const float* c, double& meanStep)
{
  double u[3], w[3];
  for (int i = 0; i < 3; ++i)
  {
    u[i] = b[i] - a[i];
    w[i] = c[i] - b[i];
  }
  const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  const double lw = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  meanStep = 0.5 * (lu + lw);
  if (!(lu > 0.0) || !(lw > 0.0))
  {
    return 0.0;
  }
  const double cosine = (u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / (lu * lw);
  return std::acos(std::max(-1.0, std::min(1.0, cosine)));
}
} // namespace

std::string validate(const FlowLineParameters& p)
{
  std::ostringstream why;
  if (!(p.kernelRadius > 0.0) || !std::isfinite(p.kernelRadius))
  {
    why << "the kernel radius must be a positive length (got " << p.kernelRadius << ")";
  }
  else if (p.seedStride < 1)
  {
    why << "SeedStride must be at least 1 (got " << p.seedStride << ")";
  }
  else if (p.pointsPerLine < 2 || p.pointsPerLine > 10000)
  {
    why << "PointsPerLine must be between 2 and 10000 (got " << p.pointsPerLine << ")";
  }
  else if (!(p.lineDuration > 0.0) || !std::isfinite(p.lineDuration))
  {
    why << "LineDuration must be a positive time in seconds (got " << p.lineDuration << ")";
  }
  else if (p.maxLines < 1)
  {
    why << "MaxLines must be at least 1";
  }
  return why.str();
}

FlowLineSet traceFlowLines(const float* xyz, const float* velocity, std::size_t n, const FlowLineParameters& p,
                           const float* seeds, std::size_t seedCount, const std::function<bool(double)>& progress)
{
  const std::string problem = validate(p);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  FlowLineSet out;
  out.offsets.push_back(0);
  if (n == 0)
  {
    return out;
  }
  ParticleNeighbourhood near;
  near.build(xyz, n, static_cast<float>(p.kernelRadius));

  // Seeds: the given points, else every seedStride-th particle.
  std::vector<float> starts;
  if (seeds)
  {
    starts.assign(seeds, seeds + 3 * seedCount);
  }
  else
  {
    for (std::size_t i = 0; i < n; i += static_cast<std::size_t>(p.seedStride))
    {
      starts.insert(starts.end(), xyz + 3 * i, xyz + 3 * i + 3);
    }
  }
  const long long count = static_cast<long long>(starts.size() / 3);
  for (float s : starts)
  {
    if (!std::isfinite(s))
    {
      throw std::invalid_argument("a seed position is NaN or infinite");
    }
  }
  std::vector<TracedLine> lines(static_cast<std::size_t>(count));
  // Traced in chunks so that progress is reported and an abort is honoured between them.
  const long long chunk = std::max<long long>(1024, count / 20);
  for (long long first = 0; first < count; first += chunk)
  {
    const long long last = std::min(count, first + chunk);
#pragma omp parallel for schedule(dynamic, 64)
    for (long long s = first; s < last; ++s)
    {
      lines[static_cast<std::size_t>(s)] = trace(near, velocity, p, &starts[3 * static_cast<std::size_t>(s)]);
    }
    if (progress && !progress(0.9 * static_cast<double>(last) / static_cast<double>(count)))
    {
      return FlowLineSet{ {}, { 0 }, {}, {}, {}, {}, {} };
    }
  }

  // Turning, then rank by length x turning (ties: longer first, then seed order) and keep the budget.
  std::vector<std::uint32_t> kept;
  for (std::size_t s = 0; s < lines.size(); ++s)
  {
    TracedLine& line = lines[s];
    const std::size_t m = line.points.size() / 3;
    if (m < 2)
    {
      continue;
    }
    for (std::size_t k = 1; k + 1 < m; ++k)
    {
      double meanStep = 0.0;
      line.turning += turnAngle(&line.points[3 * (k - 1)], &line.points[3 * k], &line.points[3 * (k + 1)], meanStep);
    }
    kept.push_back(static_cast<std::uint32_t>(s));
  }
  auto better = [&](std::uint32_t a, std::uint32_t b)
  {
    const double sa = lines[a].length * lines[a].turning, sb = lines[b].length * lines[b].turning;
    if (sa != sb)
    {
      return sa > sb;
    }
    if (lines[a].length != lines[b].length)
    {
      return lines[a].length > lines[b].length;
    }
    return a < b;
  };
  if (kept.size() > p.maxLines)
  {
    std::partial_sort(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(p.maxLines), kept.end(), better);
    kept.resize(p.maxLines);
  }
  std::sort(kept.begin(), kept.end()); // output in seed order

  for (std::uint32_t s : kept)
  {
    const TracedLine& line = lines[s];
    const std::size_t m = line.points.size() / 3;
    const std::size_t base = out.points.size() / 3;
    out.points.insert(out.points.end(), line.points.begin(), line.points.end());
    out.speed.insert(out.speed.end(), line.speed.begin(), line.speed.end());
    out.curvature.resize(base + m, 0.0f);
    for (std::size_t k = 1; k + 1 < m; ++k)
    {
      double meanStep = 0.0;
      const double angle =
        turnAngle(&line.points[3 * (k - 1)], &line.points[3 * k], &line.points[3 * (k + 1)], meanStep);
      out.curvature[base + k] = meanStep > 0.0 ? static_cast<float>(angle / meanStep) : 0.0f;
    }
    if (m > 2)
    {
      // The ends take their neighbour's value: one step has no angle of its own.
      out.curvature[base] = out.curvature[base + 1];
      out.curvature[base + m - 1] = out.curvature[base + m - 2];
    }
    out.offsets.push_back(static_cast<std::uint32_t>(base + m));
    out.length.push_back(static_cast<float>(line.length));
    out.turning.push_back(static_cast<float>(line.turning));
    out.seed.push_back(s);
  }
  if (progress)
  {
    progress(1.0);
  }
  return out;
}
} // namespace parafluid::npr
