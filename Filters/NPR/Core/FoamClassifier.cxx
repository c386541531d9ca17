#include "parafluid/npr/FoamClassifier.h"

#include "parafluid/common/Kernels.h"
#include "parafluid/common/ParticleNeighbourhood.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace parafluid::npr
{
std::string validate(const FoamParameters& p)
{
  std::ostringstream why;
  if (!(p.kernelRadius > 0.0) || !std::isfinite(p.kernelRadius))
  {
    why << "the kernel radius must be a positive length (got " << p.kernelRadius << ")";
  }
  else if (!(p.particleVolume > 0.0) || !std::isfinite(p.particleVolume))
  {
    why << "the particle volume must be positive (got " << p.particleVolume << ")";
  }
  else if (!(p.surfaceThreshold > 0.0) || !std::isfinite(p.surfaceThreshold))
  {
    why << "SurfaceThreshold must be positive (got " << p.surfaceThreshold << ")";
  }
  else if (!(p.crestThreshold > 0.0) || !std::isfinite(p.crestThreshold))
  {
    why << "CrestThreshold must be positive (got " << p.crestThreshold << ")";
  }
  else if (p.sprayNeighbours < 0)
  {
    why << "SprayNeighbours must not be negative (got " << p.sprayNeighbours << ")";
  }
  return why.str();
}

FoamScores scoreFoam(const float* xyz, std::size_t n, const FoamParameters& p,
                     const std::function<bool(double)>& progress)
{
  const std::string problem = validate(p);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  FoamScores out;
  out.score.assign(n, 0.0f);
  out.candidate.assign(n, 0);
  out.crest.assign(n, 0.0f);
  out.surface.assign(n, 0);
  if (n == 0)
  {
    return out;
  }
  const float h = static_cast<float>(p.kernelRadius);
  ParticleNeighbourhood near;
  near.build(xyz, n, h);
  const Poly6Kernel poly6(h);
  const float volume = static_cast<float>(p.particleVolume);
  const long long count = static_cast<long long>(n);

  // Each pass in blocks of particles, progress reported between them (every particle's score
  // depends on its neighbours only, so the blocks do not change the result).
  constexpr long long kBlock = 1 << 16;
  bool stopped = false;
  const auto inBlocks = [&](double from, double to, const auto& body)
  {
    for (long long first = 0; first < count && !stopped; first += kBlock)
    {
      const long long last = std::min(count, first + kBlock);
      body(first, last);
      stopped = progress && !progress(from + (to - from) * static_cast<double>(last) / static_cast<double>(count));
    }
  };

  // Pass 1: outward unit normal -grad c / |grad c|, the surface test, and the neighbour count.
  std::vector<float> normal(3 * n, 0.0f);
  std::vector<std::uint32_t> neighbours(n, 0);
  inBlocks(0.0, 0.5,
           [&](long long first, long long last)
           {
#pragma omp parallel for schedule(static)
             for (long long i = first; i < last; ++i)
             {
               float g[3] = { 0.0f, 0.0f, 0.0f };
               std::uint32_t others = 0;
               near.forEachNear(&xyz[3 * i],
                                [&](std::uint32_t j, float ex, float ey, float ez, float r2)
                                {
                                  if (j == static_cast<std::uint32_t>(i))
                                  {
                                    return;
                                  }
                                  ++others;
                                  // grad_i W(x_i - x_j) = factor * (x_i - x_j) = -factor * e
                                  const float f = -volume * poly6.gradientFactorFromSquared(r2);
                                  g[0] += f * ex;
                                  g[1] += f * ey;
                                  g[2] += f * ez;
                                });
               neighbours[i] = others;
               const float length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
               if (length * h > p.surfaceThreshold)
               {
                 out.surface[i] = 1;
                 for (int a = 0; a < 3; ++a)
                 {
                   normal[3 * i + a] = -g[a] / length; // c grows into the fluid; outward is against it
                 }
               }
             }
           });

  // Pass 2: crest potential over surface neighbours below along the normal, and the score.
  const float spray = static_cast<float>(p.sprayNeighbours);
  inBlocks(0.5, 1.0,
           [&](long long first, long long last)
           {
#pragma omp parallel for schedule(static)
             for (long long i = first; i < last; ++i)
             {
               float crest = 0.0f;
               if (out.surface[i])
               {
                 const float* ni = &normal[3 * i];
                 near.forEachNear(&xyz[3 * i],
                                  [&](std::uint32_t j, float ex, float ey, float ez, float r2)
                                  {
                                    if (j == static_cast<std::uint32_t>(i) || !out.surface[j] ||
                                        ex * ni[0] + ey * ni[1] + ez * ni[2] >= 0.0f)
                                    {
                                      return;
                                    }
                                    const float* nj = &normal[3 * j];
                                    crest += (1.0f - (ni[0] * nj[0] + ni[1] * nj[1] + ni[2] * nj[2])) *
                                             (1.0f - std::sqrt(r2) / h);
                                  });
               }
               out.crest[i] = crest;
               // Spray cue: 1 at sprayNeighbours neighbours or fewer, falling to 0 at twice as many.
               const float others = static_cast<float>(neighbours[i]);
               const float sprayCue =
                 others <= spray ? 1.0f : std::max(0.0f, 1.0f - (others - spray) / std::max(spray, 1.0f));
               out.score[i] = std::max(crest / static_cast<float>(p.crestThreshold), sprayCue);
               out.candidate[i] = out.score[i] >= 1.0f ? 1 : 0;
             }
           });
  return out;
}

void FoamHysteresis::update(const std::int64_t* ids, const std::uint8_t* candidate, std::size_t n, int persistFrames,
                            std::vector<std::uint8_t>& foam)
{
  const int persist = std::max(1, persistFrames);
  std::unordered_map<std::int64_t, State> next;
  next.reserve(n);
  foam.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    auto found = this->States.find(ids[i]);
    State s = found == this->States.end() ? State() : found->second;
    if (candidate[i] != s.foam)
    {
      // Disagreeing with the current state: count the run, switch once it is long enough.
      if (++s.run >= persist)
      {
        s.foam = candidate[i];
        s.run = 0;
      }
    }
    else
    {
      s.run = 0;
    }
    foam[i] = s.foam;
    next[ids[i]] = s;
  }
  this->States.swap(next);
}
} // namespace parafluid::npr
