#include "parafluid/SPHParameters.h"

#include "parafluid/SPHKernels.h"

#include <cmath>
#include <stdexcept>

namespace parafluid::sph
{
namespace
{
bool positiveFinite(float v)
{
  return std::isfinite(v) && v > 0.0f;
}
}

std::string SPHParameters::validate() const
{
  if (!positiveFinite(smoothingLength))
  {
    return "SmoothingLength must be a positive number of metres, got " + std::to_string(smoothingLength);
  }
  if (!positiveFinite(restDensity))
  {
    return "RestDensity must be positive (kg/m^3), got " + std::to_string(restDensity);
  }
  if (!std::isfinite(gasStiffness) || gasStiffness < 0.0f)
  {
    return "GasStiffness must be zero or positive (m^2/s^2), got " + std::to_string(gasStiffness);
  }
  if (!std::isfinite(viscosity) || viscosity < 0.0f)
  {
    return "Viscosity must be zero or positive (Pa s), got " + std::to_string(viscosity);
  }
  if (!positiveFinite(timeStep))
  {
    return "TimeStep must be a positive number of seconds, got " + std::to_string(timeStep);
  }
  if (!positiveFinite(particleMass))
  {
    return "ParticleMass must be positive (kg), got " + std::to_string(particleMass);
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
      return "DomainBounds must give min < max on every axis (axis " + std::to_string(a) + ": " +
        std::to_string(lo) + " .. " + std::to_string(hi) + ")";
    }
  }
  if (!std::isfinite(wallRestitution) || wallRestitution < 0.0f || wallRestitution > 1.0f)
  {
    return "WallRestitution must lie in [0, 1], got " + std::to_string(wallRestitution);
  }
  if (threads < 0)
  {
    return "threads must be 0 (default) or positive";
  }
  return {};
}

float latticeParticleMass(float spacing, float smoothingLength, float restDensity)
{
  if (!positiveFinite(spacing) || !positiveFinite(smoothingLength) || !positiveFinite(restDensity))
  {
    throw std::invalid_argument("particle mass: spacing, smoothing length and rest density must be positive");
  }
  if (smoothingLength / spacing > 50.0f)
  {
    throw std::invalid_argument("particle mass: smoothing length is more than 50 particle spacings");
  }
  const Poly6Kernel w(smoothingLength);
  const int reach = static_cast<int>(std::ceil(smoothingLength / spacing));
  double sum = 0.0;
  for (int k = -reach; k <= reach; ++k)
  {
    for (int j = -reach; j <= reach; ++j)
    {
      for (int i = -reach; i <= reach; ++i)
      {
        const double r2 = (double(i) * i + double(j) * j + double(k) * k) * double(spacing) * spacing;
        sum += w.valueFromSquared(static_cast<float>(r2));
      }
    }
  }
  return static_cast<float>(restDensity / sum);
}
} // namespace parafluid::sph
