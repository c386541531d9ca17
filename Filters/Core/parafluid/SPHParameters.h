#pragma once
// Parameters of the weakly compressible SPH solver (Müller et al. 2003). SI units throughout.
#include <array>
#include <string>

namespace parafluid::sph
{
struct SPHParameters
{
  float smoothingLength = 0.04f;  // h [m]: kernel support radius (about 2 particle spacings)
  float restDensity = 1000.0f;    // rho0 [kg/m^3]
  float gasStiffness = 1000.0f;   // k [m^2/s^2] in p = k (rho - rho0); sqrt(k) is the sound speed
  // mu [Pa s]: Müller's viscosity coefficient; 3.5 is the paper's water value. It is not water's
  // physical 1e-3: the term also damps the acoustic noise of a weakly compressible fluid.
  float viscosity = 3.5f;
  float timeStep = 2.0e-4f;       // dt [s]
  float particleMass = 0.0f;      // m [kg]; must be set (see latticeParticleMass)
  std::array<float, 3> gravity = { 0.0f, 0.0f, -9.81f };               // [m/s^2]
  std::array<float, 6> domainBounds = { 0.f, 1.f, 0.f, 1.f, 0.f, 1.f }; // xmin,xmax,ymin,ymax,zmin,zmax [m]
  float wallRestitution = 0.5f;   // fraction of the normal velocity kept when bouncing off a wall
  /// Free-surface particles miss neighbours, so their density is below rho0; negative pressure
  /// would pull them into clumps (tensile instability). Clamping p >= 0 avoids it.
  bool clampNegativePressure = true;
  int threads = 0;                // OpenMP threads; 0 = the OpenMP default

  /// Empty when usable, else a sentence naming the first bad parameter.
  std::string validate() const;
};

/// Mass that makes a particle inside a cubic lattice of the given spacing have exactly rest density
/// when density is summed with the poly6 kernel of radius h (the plain rho0 * spacing^3 is off by a
/// few percent for h = 2 spacings, which would make a block at rest expand or shrink at t = 0).
float latticeParticleMass(float spacing, float smoothingLength, float restDensity);
} // namespace parafluid::sph
