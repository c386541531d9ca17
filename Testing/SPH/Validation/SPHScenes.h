#pragma once
// Validation scenes of the SPH solvers: each runs one flow with a known answer (an analytic
// solution or a published experiment) and returns its error, run time and size. Shared by the
// ParaFluidSPHValidation program (full resolutions, CSV) and the ctest short versions.
// Nothing here is tuned to the data it is judged against: every scene uses the solver's defaults
// (water: rho0 1000 kg/m^3, nu 1e-6 m^2/s) unless the flow itself sets a parameter (the Reynolds
// number of an analytic flow).
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/Simulation.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace parafluid::validation
{
constexpr float kGravity = 9.81f;               // [m/s^2]
constexpr float kRho0 = 1000.0f;                // [kg/m^3]
constexpr float kWaterSurfaceTension = 0.0728f; // water-air at 20 C [N/m]

const char* solverName(sph::PressureSolverType solver);

/// The kernel support radius in particle spacings the scenes give a solver (2, 2 and
/// sph::kDeltaSPHSupport for WCSPH, DFSPH and δ-SPH unless set).
void setKernelRatio(sph::PressureSolverType solver, float ratio);
float kernelRatio(sph::PressureSolverType solver);
/// δ-SPH's SPHParameters::pushHighPass in the scenes (on unless set).
void setPushHighPass(bool on);
/// For probes of the solvers' limits: DFSPH's SPHParameters::densityTolerance and every solver's
/// maxTimeStep in the scenes (0 keeps the solver's default).
void setSolveLimits(float densityTolerance, float maxTimeStep);

/// Water of the given solver at h = kernelRatio spacings in `domain`. Müller's WCSPH (the seed method) keeps
/// its paper's 3.5 Pa s, without which it rings; the others have water's viscosity only.
sph::SPHParameters water(sph::PressureSolverType solver, float spacing, const std::array<float, 6>& domain);

ParticleState lattice(const std::array<double, 6>& box, double spacing);

struct RunCost
{
  long long particles = 0, steps = 0;
  double seconds = 0.0; // wall-clock
};

/// A column 0.2 m wide and high, `across` particles wide (a slab 4 particles thick between
/// free-slip walls), settled 0.4 s, then each particle's output pressure averaged over 0.2 s
/// against rho0 g depth. profile: rows solver,across,z,pressure,reference.
struct Hydrostatic
{
  RunCost cost;
  double error = 0.0;       // relative L2 over particles
  double compression = 0.0; // mean (rho - rho0) / rho0
  // The error split by depth (see ErrorByDepth): error^2 = layerMean^2 + withinLayer^2.
  double layerMeanError = 0.0, withinLayerError = 0.0;
};

/// A relative L2 error of values against references, split over depth layers one particle spacing
/// thick: the part that the layers' mean departures carry (an offset or a wrong slope, such as a
/// surface layer's missing pressure) and the part of the particles' scatter about their layer's
/// mean (noise from a disordered packing). The two add in squares to the whole:
/// sum_i e_i^2 = sum_L [n_L mean_L(e)^2 + sum_(i in L) (e_i - mean_L(e))^2], e_i = value_i - reference_i,
/// each divided by sum_i reference_i^2.
struct ErrorByDepth
{
  double total = 0.0, layerMean = 0.0, withinLayer = 0.0;
};
/// Layers are z / spacing rounded down; z, value and reference are per particle, of one length.
ErrorByDepth splitErrorByDepth(const std::vector<double>& z, const std::vector<double>& value,
                               const std::vector<double>& reference, double spacing);
Hydrostatic hydrostatic(sph::PressureSolverType solver, int across, std::ostream* profile = nullptr,
                        sph::Backend backend = sph::Backend::CPU);

/// A tank 0.5 m deep (and as long) left at rest for `duration` seconds.
struct StillWater
{
  RunCost cost;
  double largestSpeed = 0.0;  // over the last second, relative to sqrt(g H)
  double pressureError = 0.0; // relative L2 of the output pressure against rho0 g depth at the end
  double closestToWall = 0.0; // smallest distance of a particle to a wall, in spacings
  double highestDrift = 0.0;  // largest displacement of a particle from its start, in spacings
};
StillWater stillWater(sph::PressureSolverType solver, int across, double duration);

/// A periodic cube of water `across` particles on a side (12.5 mm apart, the still-water tank's
/// spacing at 40 across) without gravity, under a uniform 3.9 kPa (0.4 m of water), started on its
/// simple cubic lattice with 1e-4 spacings of noise, for 1.5 s: a fluid has no shear stiffness, so
/// nothing should move; a lattice that the pressure forces shear apart grows a transverse wave.
/// curves: rows solver,across,t,rms_speed,largest_speed (the largest over each 0.25 s).
struct PressurisedLattice
{
  RunCost cost;
  double rmsSpeed = 0.0;     // at the end [m/s]
  double largestSpeed = 0.0; // over the last 0.25 s [m/s]
  double meanPressure = 0.0; // at the end [Pa]
};
PressurisedLattice pressurisedLattice(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr);

/// Martin & Moyce (1952): a column a = 2.25 in wide and 2a high released in a tank 6a long; the
/// surge front Z = x/a against T = t sqrt(2 g / a), compared up to T = 3, and the residual
/// column height at the left wall h / 2a against tau = t sqrt(g / a). curves: rows
/// solver,across,T,Z,height.
struct DamBreak
{
  RunCost cost;
  double frontMeanError = 0.0, frontMaxError = 0.0;   // relative to the experiment
  double heightMeanError = 0.0, heightMaxError = 0.0; // relative to the experiment
  double meanCompression = 0.0;
};
DamBreak martinMoyce(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr);

/// Lobovsky et al. (2014), H = 300 mm: a column 600 mm long and 300 mm high in a tank 1610 mm
/// long; the pressure on the downstream wall at 3 mm above the floor (sensor 1) against
/// t sqrt(g / H); `across` particles over the column's height. curves: rows solver,across,t*,p*.
struct Lobovsky
{
  RunCost cost;
  double peakTime = 0.0, peakPressure = 0.0;           // first peak, t sqrt(g/H) and p / (rho0 g H)
  double peakTimeError = 0.0, peakPressureError = 0.0; // relative to the experiment's first peak
  double frontError = 0.0; // the time the front reaches the wall, relative to the experiment's
};
Lobovsky lobovsky(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr);

/// Taylor-Green vortex at Re = U L / nu = 100 in a periodic square of side L = 1 m (a periodic slab
/// three smoothing lengths thick): kinetic energy against exp(-16 pi^2 nu t / L^2) over one decay
/// time. curves: rows solver,across,t,energy_ratio,exact.
struct TaylorGreen
{
  RunCost cost;
  double decayError = 0.0; // largest relative error of E(t)/E(0) over one decay time
};
TaylorGreen taylorGreen(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr);

/// Poiseuille flow between no-slip plates H = 0.1 m apart (periodic along the flow), driven by a
/// body force, nu = 0.01 m^2/s (Re = 0.1); the layer-averaged velocity after t = H^2 / nu against
/// the parabola. curves: rows solver,across,z,u,exact.
struct Poiseuille
{
  RunCost cost;
  double profileError = 0.0;   // largest |u - exact| over the layers, relative to the peak velocity
  int viscosityIterations = 0; // DFSPH: mean CG iterations per step
};
Poiseuille poiseuille(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr);

/// The first sloshing mode of a tank L = 1 m long with water h = 0.5 m deep, started with the
/// velocity field of the linear standing wave of amplitude 10 mm; its frequency from the
/// horizontal centre of mass against omega^2 = g k tanh(k h), k = pi / L. curves: rows
/// solver,across,t,x_centre.
struct StandingWave
{
  RunCost cost;
  double frequency = 0.0, exact = 0.0;
  double frequencyError = 0.0; // relative
};
StandingWave standingWave(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr,
                          sph::Backend backend = sph::Backend::CPU);

/// A weightless water drop of radius 2.5 mm, `across` particles over its radius, stretched by
/// `stretch` along x (volume kept) and let go: the period of its l = 2 oscillation, from the zero
/// crossings of (<x^2> - <y^2>) / (<x^2> + <y^2>), against Rayleigh's (1879)
/// omega^2 = 8 sigma / (rho R^3) (32.7 ms), with sigma water's 0.0728 N/m. curves: rows
/// solver,across,t,elongation.
struct Drop
{
  RunCost cost;
  double period = 0.0, rayleigh = 0.0; // [s]
  double periodError = 1.0;            // relative; 1 when fewer than three zero crossings
  double sigmaRatio = 0.0;             // the surface tension the period implies, over the one set
  double largestDensity = 0.0;         // over rho0, the largest of the steps
  int crossings = 0;
};
Drop oscillatingDrop(sph::PressureSolverType solver, int across, std::ostream* curves = nullptr,
                     sph::SurfaceTensionModel model = sph::SurfaceTensionModel::Akinci, double stretch = 0.1,
                     double duration = 0.1, sph::Backend backend = sph::Backend::CPU);
} // namespace parafluid::validation
