#include "parafluid/clouds/StableFluids.h"

#include "BodyForces.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace parafluid::clouds
{
StableFluids::StableFluids(const StableFluidsParameters& parameters)
  : P(parameters)
{
  double cells = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    if (P.resolution[a] < 2 || P.resolution[a] > 1024)
    {
      throw std::invalid_argument("Resolution must be 2 to 1024 cells per axis (got " +
                                  std::to_string(P.resolution[a]) + ")");
    }
    cells *= P.resolution[a];
  }
  if (cells > double(1 << 27))
  {
    throw std::invalid_argument("Resolution asks for more than 2^27 cells");
  }
  if (!(P.cellSize > 0.0) || !std::isfinite(P.cellSize))
  {
    throw std::invalid_argument("the cell size must be positive and finite");
  }
  if (!(P.viscosity >= 0.0) || !(P.diffusivity >= 0.0) || !(P.vorticity >= 0.0))
  {
    throw std::invalid_argument("Viscosity, Diffusivity and Vorticity must be >= 0");
  }
  if (!(P.projectionTolerance > 0.0 && P.projectionTolerance < 1.0) || P.projectionIterations < 1)
  {
    throw std::invalid_argument("ProjectionTolerance must lie in (0, 1) and ProjectionIterations be >= 1");
  }
  if (!std::isfinite(P.emitterDensity) || !std::isfinite(P.emitterTemperature) || !std::isfinite(P.emitterSpeed) ||
      !std::isfinite(P.buoyancyDensity) || !std::isfinite(P.buoyancyHeat) || !std::isfinite(P.ambientTemperature))
  {
    throw std::invalid_argument("the emitter's and the buoyancy's values must be finite");
  }
  this->Grid.resize(P.resolution[0], P.resolution[1], P.resolution[2], P.cellSize);
  std::copy(P.origin, P.origin + 3, this->Grid.origin.begin());
  std::copy(P.open, P.open + 6, this->Grid.open.begin());
  std::fill(this->Grid.temperature.values.begin(), this->Grid.temperature.values.end(), P.ambientTemperature);
  this->Forces = std::make_shared<detail::ForceScratch>();
}

void StableFluids::applySources(double dt)
{
  (void)dt;
  StaggeredGrid& g = this->Grid;
  const double hot = P.ambientTemperature + P.emitterTemperature;
  auto inject = [&](std::size_t cell)
  {
    g.density.values[cell] = std::max(g.density.values[cell], P.emitterDensity);
    g.temperature.values[cell] = std::max(g.temperature.values[cell], hot);
  };
  // Point sources: the cell holding each point, and the faces of that cell get the speed.
  GridArray* faces[3] = { &g.u, &g.v, &g.w };
  for (std::size_t n = 0; n + 2 < this->PointSources.size(); n += 3)
  {
    int c[3];
    bool inside = true;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double s = (this->PointSources[n + axis] - g.origin[axis]) / g.h;
      const int dims[3] = { g.nx, g.ny, g.nz };
      inside = inside && std::isfinite(s) && s >= 0.0 && s < dims[axis];
      c[axis] = inside ? static_cast<int>(s) : 0;
    }
    if (!inside)
    {
      continue;
    }
    inject(g.density.index(c[0], c[1], c[2]));
    for (int axis = 0; axis < 3; ++axis)
    {
      const double speed = -P.emitterSpeed * P.gravityDirection[axis];
      if (speed != 0.0)
      {
        int hi[3] = { c[0], c[1], c[2] };
        ++hi[axis];
        faces[axis]->at(c[0], c[1], c[2]) = speed;
        faces[axis]->at(hi[0], hi[1], hi[2]) = speed;
      }
    }
  }
  if (!P.emitter)
  {
    return;
  }
  auto inside = [&](const GridArray& a, int i, int j, int k)
  {
    const int idx[3] = { i, j, k };
    for (int axis = 0; axis < 3; ++axis)
    {
      const double x = g.origin[axis] + g.h * (idx[axis] + a.offset[axis]);
      if (x < P.emitterBox[2 * axis] || x > P.emitterBox[2 * axis + 1])
      {
        return false;
      }
    }
    return true;
  };
  // The samples of `a` that may lie in the box (one more each side for rounding; inside() decides).
  auto span = [&](const GridArray& a, int axis, int& first, int& last)
  {
    const double lo = (P.emitterBox[2 * axis] - g.origin[axis]) / g.h - a.offset[axis];
    const double hi = (P.emitterBox[2 * axis + 1] - g.origin[axis]) / g.h - a.offset[axis];
    first = static_cast<int>(std::max(std::floor(lo) - 1.0, 0.0));
    last = static_cast<int>(std::min(std::ceil(hi) + 1.0, a.dims[axis] - 1.0));
  };
  auto forEachInside = [&](const GridArray& a, auto&& f)
  {
    int first[3], last[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      span(a, axis, first[axis], last[axis]);
    }
#pragma omp parallel for schedule(static)
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i)
        {
          if (inside(a, i, j, k))
          {
            f(a.index(i, j, k));
          }
        }
  };
  forEachInside(g.density, inject);
  for (int axis = 0; axis < 3; ++axis)
  {
    const double speed = -P.emitterSpeed * P.gravityDirection[axis];
    if (speed == 0.0)
    {
      continue;
    }
    GridArray& f = *faces[axis];
    forEachInside(f, [&](std::size_t id) { f.values[id] = speed; });
  }
}

void StableFluids::applyForces(double dt)
{
  StaggeredGrid& g = this->Grid;
  detail::ForceScratch& scratch = *this->Forces;
  GridArray* faces[3] = { &g.u, &g.v, &g.w };
  // Buoyancy per cell, then on each face the mean of the cells either side (the one cell at a wall).
  std::vector<double>& lift = scratch.lift;
  lift.resize(g.cells());
  const double* rho = g.density.values.data();
  const double* temperature = g.temperature.values.data();
  const long long cells = static_cast<long long>(g.cells());
#pragma omp parallel for schedule(static)
  for (long long c = 0; c < cells; ++c)
  {
    lift[c] = -P.buoyancyDensity * rho[c] + P.buoyancyHeat * (temperature[c] - P.ambientTemperature);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double up = -P.gravityDirection[axis];
    if (up != 0.0)
    {
      detail::addCellValuesToFaces(g, *faces[axis], axis, lift.data(), dt * up, false);
    }
  }
  if (P.vorticity > 0.0)
  {
    detail::addVorticityConfinement(g, P.vorticity, dt, scratch);
  }
}

void StableFluids::step(double dt)
{
  if (!(dt > 0.0) || !std::isfinite(dt))
  {
    throw std::invalid_argument("the time step must be positive and finite");
  }
  StaggeredGrid& g = this->Grid;
  auto lap = std::chrono::steady_clock::now();
  auto elapsed = [&lap]()
  {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - lap).count();
    lap = now;
    return ms;
  };
  this->applySources(dt);
  this->applyForces(dt);
  setBoundaryVelocities(g);
  this->Timings.forces = elapsed();
  // Every field is carried by the same (old) velocity: the scalars first.
  advectScalars(g, { { &g.density, 0.0 }, { &g.temperature, P.ambientTemperature } }, dt, P.macCormack, P.conservative,
                this->Advection.get());
  this->Timings.scalarAdvection = elapsed();
  advectVelocity(g, dt, P.macCormack, this->Advection.get());
  this->Timings.advection = this->Timings.scalarAdvection + elapsed();
  if (P.viscosity > 0.0)
  {
    for (GridArray* f : { &g.u, &g.v, &g.w })
    {
      diffuse(*f, g.h, P.viscosity, dt);
    }
  }
  if (P.diffusivity > 0.0)
  {
    diffuse(g.density, g.h, P.diffusivity, dt);
    diffuse(g.temperature, g.h, P.diffusivity, dt);
  }
  this->Timings.diffusion = elapsed();
  ProjectionOptions options;
  options.tolerance = P.projectionTolerance;
  options.maxIterations = P.projectionIterations;
  options.preconditioner = P.preconditioner;
  options.warmStart = true;
  options.workspace = this->Workspace.get();
  this->Projection = project(g, dt, options);
  this->Timings.projection = elapsed();
}

double StableFluids::totalDensity() const
{
  double sum = 0.0;
  for (double value : this->Grid.density.values)
  {
    sum += value;
  }
  return sum * this->Grid.h * this->Grid.h * this->Grid.h;
}

double StableFluids::fastestSpeed() const
{
  double fastest = P.emitter || !this->PointSources.empty() ? std::abs(P.emitterSpeed) : 0.0;
  for (const GridArray* f : { &this->Grid.u, &this->Grid.v, &this->Grid.w })
  {
    for (double value : f->values)
    {
      fastest = std::max(fastest, std::abs(value));
    }
  }
  return fastest;
}

double StableFluids::longestStableStep() const
{
  const double fastest = this->fastestSpeed();
  return fastest > 0.0 ? kMaxCellsPerStep * this->Grid.h / fastest : std::numeric_limits<double>::infinity();
}

double StableFluids::kineticEnergy() const
{
  double sum = 0.0;
  for (const GridArray* f : { &this->Grid.u, &this->Grid.v, &this->Grid.w })
  {
    for (double value : f->values)
    {
      sum += value * value;
    }
  }
  return 0.5 * sum * this->Grid.h * this->Grid.h * this->Grid.h;
}
} // namespace parafluid::clouds
