#include "parafluid/clouds/StableFluids.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
#pragma omp parallel for schedule(static)
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
      {
        if (inside(g.density, i, j, k))
        {
          inject(g.density.index(i, j, k));
        }
      }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double speed = -P.emitterSpeed * P.gravityDirection[axis];
    if (speed == 0.0)
    {
      continue;
    }
    GridArray& f = *faces[axis];
#pragma omp parallel for schedule(static)
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i)
        {
          if (inside(f, i, j, k))
          {
            f.at(i, j, k) = speed;
          }
        }
  }
}

void StableFluids::applyForces(double dt)
{
  StaggeredGrid& g = this->Grid;
  GridArray* faces[3] = { &g.u, &g.v, &g.w };
  for (int axis = 0; axis < 3; ++axis)
  {
    const double up = -P.gravityDirection[axis];
    if (up == 0.0)
    {
      continue;
    }
    GridArray& f = *faces[axis];
    const int step[3] = { axis == 0, axis == 1, axis == 2 };
#pragma omp parallel for schedule(static)
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i)
        {
          // The two cells either side of the face (one at the walls).
          const int lo[3] = { i - step[0], j - step[1], k - step[2] };
          const int hi[3] = { i, j, k };
          double rho = 0.0, heat = 0.0, count = 0.0;
          for (const int* c : { lo, hi })
          {
            if (c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < g.nx && c[1] < g.ny && c[2] < g.nz)
            {
              rho += g.density.at(c[0], c[1], c[2]);
              heat += g.temperature.at(c[0], c[1], c[2]) - P.ambientTemperature;
              count += 1.0;
            }
          }
          if (count > 0.0)
          {
            f.at(i, j, k) += dt * up * (-P.buoyancyDensity * rho + P.buoyancyHeat * heat) / count;
          }
        }
  }
  if (P.vorticity > 0.0)
  {
    this->confineVorticity(dt);
  }
}

void StableFluids::confineVorticity(double dt)
{
  StaggeredGrid& g = this->Grid;
  const int nx = g.nx, ny = g.ny, nz = g.nz;
  const std::size_t n = g.cells();
  // Cell-centred velocity, then vorticity by central differences (one-sided at the walls). The
  // arrays are kept between steps (every entry is written below): allocating ten grids a step
  // cost as much as the arithmetic.
  std::vector<double>* c = this->Scratch.centre;
  std::vector<double>* omega = this->Scratch.vorticity;
  std::vector<double>* force = this->Scratch.force;
  std::vector<double>& magnitude = this->Scratch.magnitude;
  for (int a = 0; a < 3; ++a)
  {
    c[a].resize(n);
    omega[a].resize(n);
    force[a].resize(n);
  }
  magnitude.resize(n);
  const GridArray& cell = g.density;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t id = cell.index(i, j, k);
        c[0][id] = 0.5 * (g.u.at(i, j, k) + g.u.at(i + 1, j, k));
        c[1][id] = 0.5 * (g.v.at(i, j, k) + g.v.at(i, j + 1, k));
        c[2][id] = 0.5 * (g.w.at(i, j, k) + g.w.at(i, j, k + 1));
      }
  // d f / d axis at cell (i, j, k) = id: central, one-sided at the walls.
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(nx), static_cast<std::size_t>(nx) * ny };
  const int dims[3] = { nx, ny, nz };
  auto d = [&](const std::vector<double>& f, int i, int j, int k, int axis)
  {
    const int at = axis == 0 ? i : (axis == 1 ? j : k);
    const std::size_t id = (static_cast<std::size_t>(k) * ny + j) * nx + i;
    const bool below = at > 0, above = at < dims[axis] - 1;
    const int cells = below + above;
    return cells > 0 ? (f[above ? id + stride[axis] : id] - f[below ? id - stride[axis] : id]) / (cells * g.h) : 0.0;
  };
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t id = cell.index(i, j, k);
        omega[0][id] = d(c[2], i, j, k, 1) - d(c[1], i, j, k, 2);
        omega[1][id] = d(c[0], i, j, k, 2) - d(c[2], i, j, k, 0);
        omega[2][id] = d(c[1], i, j, k, 0) - d(c[0], i, j, k, 1);
        magnitude[id] =
          std::sqrt(omega[0][id] * omega[0][id] + omega[1][id] * omega[1][id] + omega[2][id] * omega[2][id]);
      }
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t id = cell.index(i, j, k);
        double N[3] = { d(magnitude, i, j, k, 0), d(magnitude, i, j, k, 1), d(magnitude, i, j, k, 2) };
        const double len = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
        if (len < 1e-12)
        {
          force[0][id] = force[1][id] = force[2][id] = 0.0;
          continue;
        }
        for (double& v : N)
        {
          v /= len;
        }
        const double scale = P.vorticity * g.h;
        force[0][id] = scale * (N[1] * omega[2][id] - N[2] * omega[1][id]);
        force[1][id] = scale * (N[2] * omega[0][id] - N[0] * omega[2][id]);
        force[2][id] = scale * (N[0] * omega[1][id] - N[1] * omega[0][id]);
      }
      // Onto the interior faces: the mean of the two cells' forces.
#pragma omp parallel for schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t id = cell.index(i, j, k);
        if (i > 0)
          g.u.at(i, j, k) += dt * 0.5 * (force[0][id] + force[0][cell.index(i - 1, j, k)]);
        if (j > 0)
          g.v.at(i, j, k) += dt * 0.5 * (force[1][id] + force[1][cell.index(i, j - 1, k)]);
        if (k > 0)
          g.w.at(i, j, k) += dt * 0.5 * (force[2][id] + force[2][cell.index(i, j, k - 1)]);
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
  advectVelocity(g, dt, P.macCormack, this->Advection.get());
  this->Timings.advection = elapsed();
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
