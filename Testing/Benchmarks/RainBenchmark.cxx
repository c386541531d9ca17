// Rain on the CPU (arguments: OpenMP threads, default 2; then which parts: drops, runoff, sph or
// all, the default). Prints figures:
//  - one frame of 1M stateless drops (positions and velocities of every drop, which are in the
//    air, and the impacts since the last frame) over a 512^2 terrain: target <= 10 ms;
//  - rain + runoff frames with 1M drops and about 14k SPH particles (δ-SPH): the frame time with
//    the SPH advancing the frame's 1/60 s in full (its own adaptive steps), and with one SPH step
//    per frame (the seed method's "SPH every rain step"): target >= 10 frames/s;
//  - one SPH step (δ-SPH, DFSPH) of 100k particles resting on the terrain: target >= 2 frames/s;
//  - "streaks": 1M drops drawn as streaks on the CPU at 1280 x 720 (StreakRaster, the Rain
//    representation's path under a software OpenGL), and their projection alone.
#include "parafluid/common/ParticleLattice.h"
#include "parafluid/rain/GroundSurface.h"
#include "parafluid/rain/RainField.h"
#include "parafluid/rain/Runoff.h"
#include "parafluid/rain/StreakRaster.h"
#include "parafluid/sph/SPHSolver.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

using namespace parafluid;
using Clock = std::chrono::steady_clock;

namespace
{
double seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// Rolling hills over size x size metres, n x n nodes, `relief` metres high.
std::shared_ptr<HeightField> hills(double size, int n, double relief)
{
  std::vector<float> z(static_cast<std::size_t>(n) * n);
  const double h = size / (n - 1);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = i * h / size, y = j * h / size;
      z[static_cast<std::size_t>(j) * n + i] =
        static_cast<float>(relief * (0.5 + 0.25 * std::sin(6.0 * x) * std::cos(5.0 * y) + 0.25 * x));
    }
  }
  return std::make_shared<HeightField>(std::move(z), n, n, 0.0, 0.0, h, h, 0.0);
}
} // namespace

int main(int argc, char** argv)
{
  const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
  omp_set_num_threads(threads);
  const std::string parts = argc > 2 ? argv[2] : "all";
  auto run = [&](const char* part) { return parts == "all" || parts.find(part) != std::string::npos; };
  std::printf("threads %d\n", threads);

  // 1M drops in a 40 m x 40 m x 20 m box seen from 25 m in front of it (the camera of
  // rain_render_benchmark.py, 30 degrees high), 1280 x 720: the streaks drawn on the CPU.
  if (run("streaks"))
  {
    std::mt19937 generator(1);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> drops;
    const std::size_t count = 1000000;
    drops.reserve(8 * count);
    for (std::size_t k = 0; k < count; ++k)
    {
      const float diameter = 0.0005f + 0.003f * unit(generator); // [m]
      drops.insert(drops.end(), { 40.0f * unit(generator), 40.0f * unit(generator), 20.0f * unit(generator), diameter,
                                  0.1f * unit(generator), 0.1f * unit(generator), -6.0f, 6.0f / 60.0f });
    }
    rain::StreakCamera camera; // at (20, -25, 8) looking along +y, z up
    camera.worldToView = { 1, 0, 0, -20, 0, 0, 1, -8, 0, -1, 0, -25, 0, 0, 0, 1 };
    const float f = 1.0f / std::tan(15.0f * 3.14159265f / 180.0f), nearPlane = 0.1f, farPlane = 200.0f;
    const float aspect = 1280.0f / 720.0f;
    camera.viewToClip = { f / aspect,
                          0,
                          0,
                          0,
                          0,
                          f,
                          0,
                          0,
                          0,
                          0,
                          (farPlane + nearPlane) / (nearPlane - farPlane),
                          2 * farPlane * nearPlane / (nearPlane - farPlane),
                          0,
                          0,
                          -1,
                          0 };
    camera.width = 1280;
    camera.height = 720;
    camera.eye = { 20.0f, -25.0f, 8.0f };
    std::vector<float> texels(128 * 64 * 4, 0.5f);
    const rain::RadianceTable table{ texels.data(), 128, 64 };
    const rain::StreakLook look;
    rain::StreakRaster raster;
    std::vector<float> image, depth(1280 * 720, 1.0f);
    std::vector<double> draw, project;
    std::size_t drawn = 0;
    for (int frame = 0; frame < 7; ++frame)
    {
      const auto a = Clock::now();
      drawn = raster.draw(drops.data(), count, camera, look, table, depth.data(), image, threads);
      const auto b = Clock::now();
      rain::StreakRaster::Streak streak;
      std::size_t seen = 0;
      for (std::size_t k = 0; k < count; ++k)
      {
        seen += rain::StreakRaster::project(drops.data() + 8 * k, camera, look, table, streak) ? 1 : 0;
      }
      project.push_back(seconds(b, Clock::now()));
      draw.push_back(seconds(a, b));
      drawn = std::min(drawn, seen);
    }
    std::printf("streaks on the CPU: 1M drops (%zu drawn) at 1280 x 720 in %.1f ms (%d threads; projection alone, "
                "1 thread: %.1f ms) (medians)\n",
                drawn, 1e3 * median(draw), threads, 1e3 * median(project));
  }

  // 1M drops over a 64 m terrain: the drop frame alone.
  if (run("drops"))
  {
    auto ground = hills(64.0, 513, 6.0);
    rain::RainParameters p;
    p.bounds = { 0.0, 64.0, 0.0, 64.0 };
    p.cells = { 128, 128 };
    p.height = 30.0;
    p.rainfallRate = 20.0;
    p.dropsPerRealDrop = 1.0;
    // Real drops in the air over the area: scale to about a million drawn.
    const rain::DropSizeDistribution sizes(p.rainfallRate);
    p.dropsPerRealDrop = 1.0e6 / (sizes.dropsPerVolume() * 64.0 * 64.0 * 27.0);
    const auto made = Clock::now();
    rain::RainField field(p, ground);
    const double setup = seconds(made, Clock::now());
    const std::size_t n = field.dropCount();
    std::vector<float> position(3 * n), velocity(3 * n);
    std::vector<std::uint8_t> inAir(n);
    std::vector<float> water(static_cast<std::size_t>(field.cellCount()), -1e30f);
    std::vector<std::int64_t> counted;
    std::vector<rain::Impact> impacts;
    field.collectImpacts(0.0, &water, counted, impacts);
    // Medians over the frames: this machine's timings jump by 2x from run to run.
    const int frames = 120;
    std::vector<double> evaluate, collect, frame;
    std::size_t impactCount = 0;
    for (int f = 1; f <= frames; ++f)
    {
      const double t = f / 60.0;
      const auto a = Clock::now();
      field.evaluate(t, &water, position.data(), velocity.data(), inAir.data());
      const auto b = Clock::now();
      impacts.clear();
      field.collectImpacts(t, &water, counted, impacts);
      const auto c = Clock::now();
      evaluate.push_back(seconds(a, b));
      collect.push_back(seconds(b, c));
      frame.push_back(seconds(a, c));
      impactCount += impacts.size();
    }
    std::printf("drops %zu (setup %.1f ms): evaluate %.2f ms, impacts %.2f ms (%.0f a frame), frame %.2f ms "
                "(medians) [target <= 10 ms]\n",
                n, 1e3 * setup, 1e3 * median(evaluate), 1e3 * median(collect),
                static_cast<double>(impactCount) / frames, 1e3 * median(frame));
  }

  // 1M drops and ~14k SPH particles: a cloudburst on a 4 m terrain until 14k particles exist, with
  // each solver at the Rain filter's settings for it: δ-SPH, and DFSPH (its default).
  for (const auto type : { sph::PressureSolverType::DeltaSPH, sph::PressureSolverType::DFSPH })
  {
    // "runoff" runs both; "runoff-delta" or "runoff-df" (DFSPH) one.
    const bool both = run("runoff") && parts.find("runoff-") == std::string::npos;
    if (!both && !run(type == sph::PressureSolverType::DFSPH ? "runoff-df" : "runoff-delta"))
    {
      continue;
    }
    const char* const solverName = type == sph::PressureSolverType::DFSPH ? "DFSPH" : "delta-SPH";
    auto ground = hills(4.0, 129, 0.6);
    rain::RainParameters p;
    p.bounds = { 0.0, 4.0, 0.0, 4.0 };
    p.cells = { 32, 32 };
    p.height = 4.0;
    p.rainfallRate = 4000.0;
    const rain::DropSizeDistribution sizes(p.rainfallRate);
    p.dropsPerRealDrop = std::min(1.0, 1.0e6 / (sizes.dropsPerVolume() * 16.0 * 3.6));
    rain::RunoffParameters r;
    r.particleSpacing = 0.02;
    r.rainStep = 1.0 / 60.0;
    r.sph.pressureSolver = type;
    rain::Runoff runoff(p, r, ground);
    const auto fill = Clock::now();
    while (runoff.particleCount() < 14000)
    {
      runoff.advance(r.rainStep);
    }
    std::printf("runoff (%s): %zu drops, %zu particles after %.2f s of rain (filled in %.1f s)\n", solverName,
                runoff.rain().dropCount(), runoff.particleCount(), runoff.time(), seconds(fill, Clock::now()));
    const int frames = 30;
    const std::int64_t steps0 = runoff.sphSteps();
    const auto a = Clock::now();
    for (int f = 0; f < frames; ++f)
    {
      runoff.advance(r.rainStep);
    }
    const double full = seconds(a, Clock::now()) / frames;
    const double sphSteps = static_cast<double>(runoff.sphSteps() - steps0) / frames;
    // The seed's accounting: one SPH step a frame. The drop frame alone (positions of every drop,
    // impacts), and one step of this SPH state.
    const rain::RainField& field = runoff.rain();
    std::vector<float> position(3 * field.dropCount()), velocity(3 * field.dropCount());
    std::vector<std::uint8_t> inAir(field.dropCount());
    const auto b = Clock::now();
    for (int f = 0; f < frames; ++f)
    {
      field.evaluate(runoff.time() + f / 60.0, &runoff.waterLevels(), position.data(), velocity.data(), inAir.data());
    }
    const double drops = seconds(b, Clock::now()) / frames;
    sph::SPHSolver solver =
      sph::SPHSolver(runoff.water()->parameters(), runoff.water()->hostState(), rain::groundBoundary(*ground));
    const auto c = Clock::now();
    for (int f = 0; f < frames; ++f)
    {
      solver.step();
    }
    const double oneStep = seconds(c, Clock::now()) / frames;
    std::printf("runoff frame (%s), SPH over the whole 1/60 s (%.1f steps): %.1f ms = %.2f frames/s\n", solverName,
                sphSteps, 1e3 * full, 1.0 / full);
    std::printf("runoff frame (%s), one SPH step (drops %.1f ms + SPH step %.1f ms): %.2f frames/s [target >= 10]\n",
                solverName, 1e3 * drops, 1e3 * oneStep, 1.0 / (drops + oneStep));
  }

  // 100k particles resting in a layer over the terrain: δ-SPH and DFSPH (the Rain filter's default),
  // each with the terrain a wall in its sums (SPH Step's default, and the Rain filter's DFSPH) and
  // with it only stopping particles (the Rain filter's δ-SPH).
  if (run("sph"))
  {
    auto ground = hills(4.0, 129, 0.6);
    for (const auto type : { sph::PressureSolverType::DeltaSPH, sph::PressureSolverType::DFSPH })
    {
      for (const bool wall : { false, true })
      {
        sph::SPHParameters s;
        s.pressureSolver = type;
        s.meshWallDensity = wall;
        const float d = 0.02f;
        s.smoothingLength = (type == sph::PressureSolverType::DeltaSPH ? 3.0f : 2.0f) * d;
        s.particleMass = sph::latticeParticleMass(d, s.smoothingLength, s.restDensity, s.densityKernel());
        s.domainBounds = { 0.0f, 4.0f, 0.0f, 4.0f, -0.05f, 2.0f };
        std::vector<float> x, y, z;
        for (int k = 0; x.size() < 100000; ++k)
        {
          for (int j = 1; j < 199 && x.size() < 100000; ++j)
          {
            for (int i = 1; i < 199 && x.size() < 100000; ++i)
            {
              const float px = i * d, py = j * d;
              x.push_back(px);
              y.push_back(py);
              z.push_back(static_cast<float>(rain::triangulatedHeight(*ground, px, py)) + (k + 0.5f) * d);
            }
          }
        }
        sph::SPHSolver solver(s, ParticleState::atRest(x, y, z), rain::groundBoundary(*ground));
        solver.step();
        const int frames = 10;
        const auto a = Clock::now();
        for (int f = 0; f < frames; ++f)
        {
          solver.step();
        }
        const double step = seconds(a, Clock::now()) / frames;
        std::printf("100k particles: one %s step (%s) %.1f ms = %.2f frames/s [target >= 2]\n",
                    type == sph::PressureSolverType::DFSPH ? "DFSPH" : "delta-SPH",
                    wall ? "terrain a wall in the sums" : "terrain only stops particles", 1e3 * step, 1.0 / step);
      }
    }
  }
  return 0;
}
