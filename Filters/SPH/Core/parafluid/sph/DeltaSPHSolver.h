#pragma once
// δ-SPH, a modern weakly compressible scheme (Antuono, Colagrossi & Marrone 2012; as in
// DualSPHysics, Domínguez et al. 2022):
//  - density from the continuity equation, D rho_i / D t = sum_j m v_ij . grad W_ij, so a free
//    surface has no density deficit and needs no pressure clamp;
//  - density diffusion (Molteni & Colagrossi 2009) with the hydrostatic part removed (Fourtakas
//    et al. 2019), so a resting column stays hydrostatic instead of diffusing towards uniform
//    density; near a free surface (a cut neighbourhood) only the departure's fast part diffuses,
//    because the truncated kernel holds the top layers at rest slightly off hydrostatic and that
//    steady departure must not be pumped between them;
//  - Tait's equation of state p = B ((rho / rho0)^7 - 1), B = c0^2 rho0 / 7;
//  - the momentum-conserving pressure gradient -sum_j m (p_i / rho_i^2 + p_j / rho_j^2) grad W_ij,
//    whose difference part sum_j m (p_j - p_i) / (rho_i rho_j) grad W_ij is, for particles with a
//    full neighbourhood, corrected by the inverse of the neighbours' first moment (Bonet & Lok
//    1999; SPHParameters::gradientCorrection), because the plain gradient's gain depends on the
//    lattice's shear, so a sheared lattice under gravity would push back like an elastic solid.
//    Wall images then carry hydrostatically extrapolated pressure (Adami et al. 2012);
//  - the rest of that gradient, about 2 p_i / rho_i^2 sum_j m grad W_ij, is what holds particles
//    apart and a free surface together, but under pressure it is also a pair potential that gives
//    the particle lattice shear moduli (negative at 3 spacings, positive at 2.8-2.9: see
//    docs/design-notes.md). In full neighbourhoods its smooth part is taken out (SPHParameters::pushHighPass):
//    with the default support of 2.9 spacings (kDeltaSPHSupport) the lattice is then stable and has
//    no long-wave shear modulus (Testing/Benchmarks/lattice_stability.py --high-pass);
//  - Monaghan's (1992) artificial viscosity with a small alpha as the only numerical viscosity, and
//    the fluid's physical viscosity (the laminar term of SPHParameters::kinematicViscosity, by
//    Morris et al.'s 1997 operator, whose lattice error does not depend on the shear's direction);
//  - negative pressure kept, with Monaghan's (2000) tensile correction against particle pairing
//    and particle shifting (Lind et al. 2012) against the voids of stretched flow;
//  - the Wendland C2 kernel, and a kick-drift-kick leapfrog in which density moves with position;
//  - a boundary mesh as a wall in the density and pressure sums (private/MeshWall.h).
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/PressureSolver.h"
#include "parafluid/sph/SolverRegistry.h"

namespace parafluid::sph
{
/// δ-SPH's kernel support [particle spacings] when none is given: Wendland C2's lattice under
/// pressure is stable only at 2.8-2.9 spacings (Testing/Benchmarks/lattice_stability.py).
constexpr float kDeltaSPHSupport = 2.9f;

class DeltaSPHSolver final : public PressureSolver
{
public:
  /// This solver's entry of the registry (SolverRegistry.h).
  static SolverEntry registryEntry();
  void start(SimulationParts& sim) override;
  double step(SimulationParts& sim, double remaining) override;
  double signalSpeed(const SPHParameters&) const override { return this->SoundSpeed; }
  void permute(SimulationParts& sim, const std::vector<std::uint32_t>& order, std::vector<float>& scratch,
               int threads) override;
  void resize(std::size_t n) override;
  std::vector<std::vector<float>*> carried() override
  {
    return { &this->WallSum, &this->Fullness, &this->SlowDeparture };
  }
  std::size_t bytes() const override
  {
    return (this->DensityRate.capacity() + this->Correction.capacity() + this->Fullness.capacity() +
            this->NextFullness.capacity() + this->SlowDeparture.capacity() + this->FullPush.capacity() +
            this->Interior.capacity()) *
           sizeof(float);
  }

  /// c0 [m/s]: SPHParameters::soundSpeed, or when that is 0, ten times the free-fall speed over the
  /// fluid's height along gravity (Monaghan 1994: density then varies by about 1 %), at least ten
  /// times the fastest initial speed and (with surface tension) the speed of its cohesive pressure.
  static double automaticSoundSpeed(const SPHParameters& p, const ParticleState& s);
  /// The same from the fluid's height along gravity [m] and its fastest initial speed [m/s].
  static double automaticSoundSpeed(const SPHParameters& p, double height, double fastest);

  /// Density of hydrostatic equilibrium under gravity along an axis at sound speed c0 [m/s] (rest
  /// density otherwise), each particle's depth counted in columns one particle spacing [m] wide.
  static void hydrostaticDensity(const SPHParameters& p, double soundSpeed, float spacing, ParticleState& s);
  /// [s] the time over which the slow part of the density's departure follows it (SlowDeparture):
  /// sqrt(H / g) of the fluid's height H; 0 without gravity.
  static double slowDepartureTime(const SPHParameters& p, const ParticleState& s);
  static double slowDepartureTime(const SPHParameters& p, double height);

private:
  /// Pressure from density by the equation of state.
  void updatePressure(SimulationParts& sim);
  /// Accelerations into State.a*: pressure, viscosities, gravity, surface tension.
  void computeAccelerations(SimulationParts& sim);
  /// Moves interior particles down their concentration gradient (DeltaSPHSolver.cxx).
  void shiftParticles(SimulationParts& sim, float dt);
  /// rho += dt D rho / D t, with the rate from the current positions and velocities.
  void advanceDensity(SimulationParts& sim, float dt);
  /// D rho / D t into DensityRate, each particle's Correction (with the gradient correction) and
  /// FullPush; each particle's Fullness for the next step.
  void sumDensityRates(SimulationParts& sim);
  /// SlowDeparture for the particles that have none (all at a start, the added ones at a restart).
  void startSlowDeparture(SimulationParts& sim);
  /// SlowDeparture moves towards each particle's departure over SlowDepartureTime.
  void followSlowDeparture(SimulationParts& sim, float dt);

  std::vector<float> DensityRate;
  std::vector<float> Shift;      // 3 per particle
  std::vector<float> WallSum;    // the mesh wall's sum at each particle when its density last moved
  std::vector<float> Correction; // 6 per particle: the gradient correction L - C I (symmetric)
  bool CorrectionFresh = false;  // Correction and FullPush summed where the particles are now
  // How full each particle's neighbourhood was at the last continuity pass (detail::
  // neighbourhoodFullness: 1 inside the fluid, 0 in the first two layers under a free surface).
  std::vector<float> Fullness, NextFullness;
  // Each particle's fullness times its G = sum_j m grad W_ij (wall images included), summed with
  // the density rates; x, y and z one after the other (n each), channels of the force pass, which
  // smooths them for the push's high pass (SPHParameters::pushHighPass).
  std::vector<float> FullPush;
  // How far inside the fluid each particle is, for the same: its fullness times the smallest of its
  // neighbours' (1 where no surface is within a kernel of any of them).
  std::vector<float> Interior;
  // The slow part of each particle's density departure from hydrostatic [kg/m^3], a first-order low
  // pass of it over SlowDepartureTime (up to a constant): at a free surface the diffusion acts on
  // the departure less this, the noise it is there to damp. 0 without gravity.
  std::vector<float> SlowDeparture;
  double SlowDepartureTime = 0.0; // [s], sqrt(H / g) of the fluid's height H (start); 0 without gravity
  double SoundSpeed = 0.0;
  float PressureCorrection = 1.0f; // pressure forces, see latticeGradientCorrection
};
} // namespace parafluid::sph
