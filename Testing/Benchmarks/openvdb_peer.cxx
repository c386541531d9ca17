// Peer (b) of issue 6, a benchmark-only program (OpenVDB is not a dependency of the plugin):
// OpenVDB's ParticlesToLevelSet (union of spheres as a narrow-band signed distance field), one
// Gaussian smoothing pass (LevelSetFilter), and volumeToMesh, on the same scenes as
// ParaFluidSurfaceBenchmark. Build and run with Testing/Benchmarks/openvdb_peer.sh.
//
// Sphere radius: ParticlesToLevelSet skips spheres under 1.5 voxels, so r = max(1.5 voxels, 1 d)
// (at least one spacing, so that neighbours overlap and the block has no holes). A union of such
// spheres lies about r - d/2 outside the particles' volume, so the mesh is taken at the level
// that makes the ball's mean signed radial error zero (found by bisection on the ball and reused
// on the dam break): the peer's most favourable level, not a default. PEER_SMOOTH=filter swaps the
// level-set Gaussian for a plain one (faster, the distance field is not re-normalised).
#include "SurfaceScenes.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Filter.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
// The particle-list interface ParticlesToLevelSet reads.
struct ParticleList
{
  using PosType = openvdb::Vec3R;
  const std::vector<float>& xyz;
  double radius;
  std::size_t size() const { return xyz.size() / 3; }
  void getPos(std::size_t n, openvdb::Vec3R& p) const
  {
    p = openvdb::Vec3R(xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]);
  }
  void getPosRad(std::size_t n, openvdb::Vec3R& p, openvdb::Real& r) const
  {
    this->getPos(n, p);
    r = this->radius;
  }
};

struct Surface
{
  std::vector<openvdb::Vec3s> points;
  std::size_t triangles = 0;
  double rasterSeconds = 0.0, smoothSeconds = 0.0, meshSeconds = 0.0;
  double seconds() const { return rasterSeconds + smoothSeconds + meshSeconds; }
};

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// PEER_SMOOTH=filter: a plain Gaussian (tools::Filter) without re-normalising the distance field;
// default: LevelSetFilter::gaussian, which re-normalises the narrow band after filtering.
bool plainFilter()
{
  const char* mode = std::getenv("PEER_SMOOTH");
  return mode && std::string(mode) == "filter";
}

const char* smoothingName()
{
  return plainFilter() ? "tools::Filter::gaussian(1) (no re-normalisation)" : "LevelSetFilter::gaussian(1)";
}

openvdb::FloatGrid::Ptr levelSet(const std::vector<float>& xyz, double d, double cell, Surface& out)
{
  const double voxel = cell * d;
  const double radius = std::max(1.5 * voxel, d);
  double t = now();
  openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, 3.0);
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
  raster.rasterizeSpheres(ParticleList{ xyz, radius });
  raster.finalize(true);
  out.rasterSeconds = now() - t;
  t = now();
  if (plainFilter())
  {
    openvdb::tools::Filter<openvdb::FloatGrid> filter(*grid);
    filter.gaussian(1, 1);
  }
  else
  {
    openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
    filter.gaussian(1);
  }
  out.smoothSeconds = now() - t;
  return grid;
}

void mesh(const openvdb::FloatGrid& grid, double level, Surface& out)
{
  const double t = now();
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  out.points.clear();
  openvdb::tools::volumeToMesh(grid, out.points, triangles, quads, level, 0.0, true);
  out.meshSeconds = now() - t;
  out.triangles = triangles.size() + 2 * quads.size();
}

double meanSignedRadial(const Surface& s, double radius)
{
  double sum = 0.0;
  for (const auto& p : s.points)
  {
    sum += std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]) - radius;
  }
  return s.points.empty() ? 0.0 : sum / static_cast<double>(s.points.size());
}

long residentKilobytes()
{
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r"))
  {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
    {
      resident = 0;
    }
    std::fclose(f);
  }
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

long peakKilobytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// One row of the ball table; returns the favourable level in units of d.
double ballRow(const std::vector<float>& ball, double d, double R, double cell)
{
  Surface s;
  const openvdb::FloatGrid::Ptr grid = levelSet(ball, d, cell, s);
  // Bisection on the level (world units): the mean signed error rises with the level.
  double lo = -2.0 * d, hi = 0.0;
  for (int i = 0; i < 30; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    mesh(*grid, mid, s);
    (meanSignedRadial(s, R) > 0.0 ? hi : lo) = mid;
  }
  const double level = 0.5 * (lo + hi);
  // The whole pipeline once more at that level, timed.
  Surface timed;
  const openvdb::FloatGrid::Ptr again = levelSet(ball, d, cell, timed);
  mesh(*again, level, timed);
  const double error = parafluid::benchmarks::meanRadialError(&timed.points[0][0], timed.points.size(), R) / d;
  std::printf("ball,%.2f,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%zu,%.4f\n", cell, std::max(1.5 * cell, 1.0), level / d,
              timed.seconds(), timed.rasterSeconds, timed.smoothSeconds, timed.meshSeconds, timed.triangles, error);
  std::fflush(stdout);
  return level / d;
}
} // namespace

int main(int argc, char** argv)
{
  const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
  const std::size_t particles = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1000000;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  openvdb::initialize();
  std::printf("# OpenVDB %s, %d threads\n", openvdb::getLibraryVersionString(), threads);

  // Ball R = 25 d: time and mean |r - R| at the favourable level, per cell size. Cell 0.5 goes
  // first, and the dam break runs before the finer ball, so that the peak resident size after the
  // dam break is the dam break's own.
  const double d = 0.01, R = 25 * d;
  const std::vector<float> ball = parafluid::benchmarks::jitteredBall(d, R);
  std::printf("# smoothing: %s\n", smoothingName());
  std::printf("scene,cell_d,radius_d,level_d,seconds,raster_s,smooth_s,mesh_s,triangles,mean_error_d\n");
  const double level = ballRow(ball, d, R, 0.5);

  // Dam break + 5 % splash at cell 0.5 d, with the ball's level in units of d.
  double spacing = 0.0;
  const std::vector<float> dam = parafluid::benchmarks::damBreakWithSplash(particles, spacing);
  const long before = residentKilobytes();
  Surface s;
  const openvdb::FloatGrid::Ptr grid = levelSet(dam, spacing, 0.5, s);
  mesh(*grid, level * spacing, s);
  const double grown = static_cast<double>(peakKilobytes() - before) * 1024.0;
  std::printf("dam_break_%zu,0.50,1.000,%.4f,%.4f,%.4f,%.4f,%.4f,%zu,\n", dam.size() / 3, level, s.seconds(),
              s.rasterSeconds, s.smoothSeconds, s.meshSeconds, s.triangles);
  std::printf("# dam break: peak resident size %.0f MB above that before it (%.0f bytes/particle)\n", grown / 1048576.0,
              grown / static_cast<double>(dam.size() / 3));
  std::fflush(stdout);

  ballRow(ball, d, R, 1.0);
  ballRow(ball, d, R, 0.25);
  return 0;
}
