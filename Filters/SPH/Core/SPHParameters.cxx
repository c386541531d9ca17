#include "parafluid/sph/SPHParameters.h"

#include "parafluid/common/Kernels.h"
#include "parafluid/sph/SPHParameterTable.h"
#include "parafluid/sph/SolverRegistry.h"
#include "private/AnyKernel.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace parafluid::sph
{
namespace
{
bool positiveFinite(float v)
{
  return std::isfinite(v) && v > 0.0f;
}

/// Calls f(r, dx, dz) for every site of a cubic lattice of the given spacing other than the
/// origin, out to the kernel's reach: r its distance, dx and dz its offsets along x and z [m]
/// (x_j - x_i for a particle i at the origin).
template<class F>
void forEachLatticeNeighbour(float spacing, float smoothingLength, F&& f)
{
  const int reach = static_cast<int>(std::ceil(smoothingLength / spacing));
  for (int k = -reach; k <= reach; ++k)
  {
    for (int j = -reach; j <= reach; ++j)
    {
      for (int i = -reach; i <= reach; ++i)
      {
        const double r = std::sqrt(double(i) * i + double(j) * j + double(k) * k) * spacing;
        if (r > 0.0)
        {
          f(r, double(i) * spacing, double(k) * spacing);
        }
      }
    }
  }
}
} // namespace
using detail::AnyKernel;

DensityKernel SPHParameters::densityKernel() const
{
  return solverEntry(pressureSolver).kernel;
}

std::string SPHParameters::validate() const
{
  const SolverEntry* solver = nullptr;
  for (const SolverEntry& entry : solverRegistry())
  {
    solver = entry.type == pressureSolver ? &entry : solver;
  }
  if (!solver)
  {
    return "PressureSolver " + std::to_string(static_cast<int>(pressureSolver)) + " is not a solver this build has";
  }
  const std::string range = checkParameterRanges(*this);
  if (!range.empty())
  {
    return range;
  }
  if (surfaceTension > 0.0f && surfaceTensionModel == SurfaceTensionModel::ColourField &&
      !solver->colourFieldSurfaceTension)
  {
    return std::string("SurfaceTensionModel: the colour field is not part of ") + solver->label +
           "'s force pass; choose Akinci 2013";
  }
  for (float g : gravity)
  {
    if (!std::isfinite(g))
    {
      return "Gravity must be finite";
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    const float lo = domainBounds[2 * a];
    const float hi = domainBounds[2 * a + 1];
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    {
      return "DomainBounds must give min < max on every axis (axis " + std::to_string(a) + ": " + std::to_string(lo) +
             " .. " + std::to_string(hi) + ")";
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    if (periodic[a] && !(domainBounds[2 * a + 1] - domainBounds[2 * a] >= 3.0f * smoothingLength))
    {
      return std::string("a periodic axis must be at least 3 smoothing lengths long (axis ") + "xyz"[a] + ": " +
             std::to_string(domainBounds[2 * a + 1] - domainBounds[2 * a]) + " m, SmoothingLength " +
             std::to_string(smoothingLength) + " m)";
    }
  }
  if (threads < 0)
  {
    return "threads must be 0 (default) or positive";
  }
  if (solver->maximumSupport > 0.0f)
  {
    const float ratio =
      smoothingLength / latticeSpacingForMass(particleMass, smoothingLength, restDensity, densityKernel());
    if (!(ratio <= solver->maximumSupport))
    {
      char limits[96];
      std::snprintf(limits, sizeof(limits), "at most %g particle spacings (%g is the default), got %g",
                    solver->maximumSupport, solver->defaultSupport, ratio);
      return std::string(solver->label) + " needs SmoothingLength of " + limits +
             "; lower it or choose another PressureSolver";
    }
  }
  return {};
}

float latticeParticleMass(float spacing, float smoothingLength, float restDensity, DensityKernel kernel)
{
  if (!positiveFinite(spacing) || !positiveFinite(smoothingLength) || !positiveFinite(restDensity))
  {
    throw std::invalid_argument("particle mass: spacing, smoothing length and rest density must be positive");
  }
  if (smoothingLength / spacing > 50.0f)
  {
    throw std::invalid_argument("particle mass: smoothing length is more than 50 particle spacings");
  }
  const AnyKernel w(kernel, smoothingLength);
  const int reach = static_cast<int>(std::ceil(smoothingLength / spacing));
  double sum = 0.0;
  for (int k = -reach; k <= reach; ++k)
  {
    for (int j = -reach; j <= reach; ++j)
    {
      for (int i = -reach; i <= reach; ++i)
      {
        const double r2 = (double(i) * i + double(j) * j + double(k) * k) * double(spacing) * spacing;
        sum += w.value(static_cast<float>(std::sqrt(r2)));
      }
    }
  }
  return static_cast<float>(restDensity / sum);
}

float latticeSpacingForMass(float particleMass, float smoothingLength, float restDensity, DensityKernel kernel)
{
  // The lattice mass grows with the spacing; bisect between h / 20 and h.
  float lo = smoothingLength / 20.0f, hi = smoothingLength;
  for (int k = 0; k < 40; ++k)
  {
    const float mid = 0.5f * (lo + hi);
    (latticeParticleMass(mid, smoothingLength, restDensity, kernel) < particleMass ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

float latticeSpikyGradientCorrection(float spacing, float smoothingLength)
{
  if (!positiveFinite(spacing) || !positiveFinite(smoothingLength) || smoothingLength / spacing > 50.0f)
  {
    return 1.0f;
  }
  // V from the poly6 density of the lattice (what Müller's WCSPH measures), the moment from spiky.
  const double volume = latticeParticleMass(spacing, smoothingLength, 1.0f, DensityKernel::Poly6);
  const SpikyKernel spiky(smoothingLength);
  double moment = 0.0;
  forEachLatticeNeighbour(spacing, smoothingLength,
                          [&](double r, double, double dz)
                          { moment -= spiky.radialDerivative(static_cast<float>(r)) / r * dz * dz; });
  const double c = volume * moment;
  return c > 0.0 ? static_cast<float>(1.0 / c) : 1.0f;
}

float latticeLaplacianCorrection(float spacing, float smoothingLength, DensityKernel kernel, bool spikyGradient)
{
  if (!positiveFinite(spacing) || !positiveFinite(smoothingLength) || smoothingLength / spacing > 50.0f)
  {
    return 1.0f;
  }
  // The operator 10 sum_j V (v_ij . x_ij) / (r^2 + eta^2) grad W_ij applied to the shear flow
  // v = (z^2 / 2, 0, 0), whose Laplacian is (1, 0, 0), at a particle at the origin of the lattice.
  const double volume = latticeParticleMass(spacing, smoothingLength, 1.0f, kernel);
  const AnyKernel w(kernel, smoothingLength);
  const SpikyKernel spiky(smoothingLength);
  const double eta2 = 0.01 * 0.25 * double(smoothingLength) * smoothingLength;
  double laplacian = 0.0;
  forEachLatticeNeighbour(spacing, smoothingLength,
                          [&](double r, double offsetX, double offsetZ)
                          {
                            const auto rf = static_cast<float>(r);
                            const double gradient = (spikyGradient ? spiky.radialDerivative(rf) : w.derivative(rf)) / r;
                            const double dx = -offsetX, dz = -offsetZ; // x_i - x_j
                            const double relative = -0.5 * dz * dz;    // v_i - v_j (x component)
                            laplacian += 10.0 * volume * relative * dx / (r * r + eta2) * gradient * dx;
                          });
  return laplacian > 0.0 ? static_cast<float>(1.0 / laplacian) : 1.0f;
}

float latticeMorrisLaplacianCorrection(float spacing, float smoothingLength, DensityKernel kernel)
{
  if (!positiveFinite(spacing) || !positiveFinite(smoothingLength) || smoothingLength / spacing > 50.0f)
  {
    return 1.0f;
  }
  // The operator applied to the shear flow v = (z^2 / 2, 0, 0) (Laplacian (1, 0, 0)) at a particle
  // at the origin of the lattice: v_i - v_j = -dz^2 / 2 and x_ij . grad W = r dW/dr.
  const double volume = latticeParticleMass(spacing, smoothingLength, 1.0f, kernel);
  const AnyKernel w(kernel, smoothingLength);
  const double eta2 = 0.01 * 0.25 * double(smoothingLength) * smoothingLength;
  double laplacian = 0.0;
  forEachLatticeNeighbour(
    spacing, smoothingLength,
    [&](double r, double, double dz)
    { laplacian += 2.0 * volume * r * w.derivative(static_cast<float>(r)) / (r * r + eta2) * (-0.5 * dz * dz); });
  return laplacian > 0.0 ? static_cast<float>(1.0 / laplacian) : 1.0f;
}

float latticeGradientCorrection(float spacing, float smoothingLength, DensityKernel kernel)
{
  if (!positiveFinite(spacing) || !positiveFinite(smoothingLength) || smoothingLength / spacing > 50.0f)
  {
    return 1.0f;
  }
  const AnyKernel w(kernel, smoothingLength);
  const int reach = static_cast<int>(std::ceil(smoothingLength / spacing));
  double sum = 0.0, moment = 0.0;
  for (int k = -reach; k <= reach; ++k)
  {
    for (int j = -reach; j <= reach; ++j)
    {
      for (int i = -reach; i <= reach; ++i)
      {
        const double r = std::sqrt(double(i) * i + double(j) * j + double(k) * k) * spacing;
        const auto rf = static_cast<float>(r);
        sum += w.value(rf);
        if (r > 0.0)
        {
          const double dWdr = w.derivative(rf);
          const double dz = double(k) * spacing;
          moment -= dWdr / r * dz * dz; // -(dW/dz)(z_i - z_j) with z_i - z_j = -dz
        }
      }
    }
  }
  // V = 1 / sum (the volume that gives rest density), so C = moment / sum.
  const double c = moment / sum;
  return c > 0.0 ? static_cast<float>(1.0 / c) : 1.0f;
}
} // namespace parafluid::sph
