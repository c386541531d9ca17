#pragma once
// Parameters of the SPH solver: δ-SPH (a modern weakly compressible scheme: Tait equation of state,
// Wendland C2, density diffusion), Bender & Koschier (2015) divergence-free SPH, or Müller et al.
// (2003) weakly compressible SPH, the seed method. SI units throughout. The defaults are water.
#include "parafluid/common/Kernels.h"

#include <array>
#include <string>

namespace parafluid::sph
{
enum class PressureSolverType
{
  WCSPH,   // Müller's equation of state p = k (rho - rho0), explicit (the seed method)
  DFSPH,   // divergence-free SPH: density and divergence solves, incompressible within a tolerance
  DeltaSPH // Tait equation of state, continuity density with δ-SPH diffusion, Wendland C2, explicit
};

enum class SurfaceTensionModel
{
  ColourField,   // Müller et al. 2003: sigma times the colour field's curvature at the surface
  Akinci,        // Akinci, Akinci & Teschner 2013: cohesion and curvature terms (SurfaceTension.cxx)
  AkinciCohesion // the same paper's cohesion alone, scaled to sigma by itself
};

/// How DFSPH's implicit viscosity system is solved (both matrix-free, Jacobi-preconditioned
/// conjugate gradients; ParaFluidSPHBenchmark measures one against the other).
enum class ViscositySolver
{
  HandWrittenCG,
  EigenCG
};

enum class WallFriction
{
  FreeSlip,
  NoSlip,
  LogLaw
};

struct SPHParameters
{
  PressureSolverType pressureSolver = PressureSolverType::DeltaSPH;
  float smoothingLength = 0.04f; // h [m]: kernel support radius (about 2 particle spacings)
  float restDensity = 1000.0f;   // rho0 [kg/m^3]
  float gasStiffness = 1000.0f;  // k [m^2/s^2] in p = k (rho - rho0); sqrt(k) is the sound speed (WCSPH)
  // nu [m^2/s]: the fluid's kinematic viscosity, the physical (laminar) viscous stress of every
  // solver (δ-SPH: the operator of Morris et al. 1997; DFSPH and Müller's: Monaghan 2005 / Weiler et
  // al. 2018); water at 20 °C: 1.0e-6, honey
  // about 1e-2. DFSPH solves it implicitly, so a high value does not shorten the step.
  float kinematicViscosity = 1.0e-6f;
  // mu [Pa s]: the extra viscosity of Müller's seed method (its paper uses 3.5 for water, 3500
  // times water's 1e-3: it also damps the acoustic noise of that scheme). 0, the default, skips it.
  float viscosity = 0.0f;
  // δ-SPH: Monaghan's artificial viscosity alpha (its only numerical viscosity; 0.01-0.02 in the
  // δ-SPH literature), the density-diffusion coefficient delta (0.1, Molteni & Colagrossi 2009;
  // near a free surface it acts on the fast part of the density only, see DeltaSPHSolver.h),
  // and the speed of sound c0 [m/s] (0: ten times the free-fall speed over the fluid's height).
  float artificialViscosity = 0.01f;
  float densityDiffusion = 0.1f;
  float soundSpeed = 0.0f;
  // δ-SPH: shift interior particles towards uniform spacing (Lind et al. 2012, with δ+-SPH's
  // coefficient, Sun et al. 2017). Off by default because it corrects neither density nor velocity
  // for the move; on, it keeps stretched flow (a vortex) evenly sampled.
  bool particleShifting = false;
  // δ-SPH: correct the pressure gradient of every particle with a full neighbourhood (its wall
  // images included) by the inverse of its neighbours' first moment (Bonet & Lok 1999), with the
  // wall images' pressure extrapolated hydrostatically (Adami et al. 2012), because the plain
  // gradient's gain changes as the particle lattice shears; free-surface particles keep it plain.
  bool gradientCorrection = true;
  // δ-SPH: inside the fluid (no free surface within a kernel of a particle or of its neighbours),
  // take the smooth part out of the rest of the symmetric pressure force, 2 p_i / rho_i^2 G_i with
  // G_i = sum_j m grad W_ij: add 2 p_i / rho_i^2 times the Shepard mean of the neighbours' G over
  // the same kernel. G is zero on a regular lattice and large only particle by particle, so what
  // this removes is the lattice's long-wave shear stiffness under pressure, a spurious elasticity,
  // while the push that keeps particles apart (and a wall's own image's) stays. Near a surface the
  // force is the plain one: there G is the surface's push. With it the lattice under pressure is
  // stable at 2.8-2.9 spacings with no long-wave shear modulus (Testing/Benchmarks/README.md).
  bool pushHighPass = true;
  // sigma [N/m]: surface tension (water-air: 0.0728); 0 skips it. surfaceTensionModel picks the force.
  float surfaceTension = 0.0f;
  SurfaceTensionModel surfaceTensionModel = SurfaceTensionModel::Akinci;
  // A particle is on the surface when |grad c| > surfaceThreshold / h (grad c ~ 1/h across a surface).
  float surfaceThreshold = 0.1f;
  float particleMass = 0.0f;                                            // m [kg]; must be set (see latticeParticleMass)
  std::array<float, 3> gravity = { 0.0f, 0.0f, -9.81f };                // [m/s^2]
  std::array<float, 6> domainBounds = { 0.f, 1.f, 0.f, 1.f, 0.f, 1.f }; // xmin,xmax,ymin,ymax,zmin,zmax [m]
  float wallRestitution = 0.5f; // fraction of the normal velocity kept when bouncing off a wall
  // Tangential stress of the box walls on the fluid (the normal condition is the same for all):
  //  - FreeSlip: none; the fluid slides along the walls;
  //  - NoSlip: the fluid sticks, through the viscous term with reversed-velocity wall images (see
  //    WallMirrors.h). Right for a fluid whose viscosity is resolved (honey, lava, slow flow); with
  //    Müller's extra Viscosity of 3.5 Pa s it brakes water as a 3500 times thicker liquid would;
  //  - LogLaw: the turbulent law of the wall (TurbulentWallLaw.h) with the fluid's molecular
  //    kinematic viscosity wallKinematicViscosity, applied to the layer of particles within one
  //    spacing of a wall: the unresolved boundary layer of real water.
  WallFriction wallFriction = WallFriction::FreeSlip;
  // Which walls the friction acts on, in the order xmin, xmax, ymin, ymax, zmin, zmax (a symmetry
  // plane, for example the side walls of a slab that stands in for a 2-D flow, stays free-slip).
  std::array<bool, 6> frictionWalls = { true, true, true, true, true, true };
  float wallKinematicViscosity = 1.0e-6f; // nu [m^2/s] for LogLaw; water at 20 °C is 1.0e-6
  float boundaryDamping = 0.5f;           // fraction of the normal velocity lost when bouncing off a boundary mesh
  // DFSPH and δ-SPH: a boundary mesh adds to a nearby particle's density and pressure sums what the
  // fluid's rest lattice continued beyond it would (a wall-weight table, private/MeshWall.h), so
  // water rests on it at rest density instead of packing onto it. Off (and in Müller's WCSPH), the
  // mesh only stops particles.
  bool meshWallDensity = true;
  // Periodic axes (x, y, z): a particle leaving through one face of the domain comes back through
  // the opposite one, and neighbours are found across the pair of faces; those faces are no walls.
  // A periodic axis must be at least three smoothing lengths long.
  std::array<bool, 3> periodic = { false, false, false };

  // Time stepping. With adaptiveTimeStep the step is the smallest of the CFL condition
  // lambda h / (c + v_max) (c = sqrt(k) for WCSPH, c0 for δ-SPH, 0 for DFSPH), the viscous
  // conditions h^2 rho0 / (40 mu) and (explicit solvers) 0.03 h^2 / nu, the force condition
  // 0.25 sqrt(h / a_max), the capillary condition sqrt(rho0 h^3 / (2 pi sigma)), and maxTimeStep;
  // else it is timeStep.
  bool adaptiveTimeStep = true;
  float cflNumber = 0.2f;     // lambda, relative to the support radius h (= 0.4 particle spacings)
  float maxTimeStep = 0.005f; // [s]
  float timeStep = 2.0e-4f;   // dt [s] when adaptiveTimeStep is off

  // DFSPH: the density solve iterates until the mean compression (rho* - rho0) / rho0 is below
  // densityTolerance; the divergence solve until the mean dt (D rho / D t) / rho0 is below
  // divergenceTolerance. Either stops after maxPressureIterations.
  float densityTolerance = 0.001f;
  float divergenceTolerance = 0.001f;
  int maxPressureIterations = 100;
  // DFSPH: the density solve by a conjugate gradient on the particles under pressure (a
  // symmetric system: the divergence is the transpose of the symmetric pressure gradient), which
  // carries pressure through a column N particles deep in O(N) iterations where Jacobi's take
  // O(N^2); false: Jacobi, as Bender & Koschier's implementation. The divergence solve, which
  // corrects what is left within a step, stays Jacobi.
  bool pressureConjugateGradient = true;
  // DFSPH's implicit viscosity: CG until the residual is below viscosityTolerance of the right-hand
  // side, at most maxPressureIterations iterations.
  float viscosityTolerance = 0.01f;
  ViscositySolver viscositySolver = ViscositySolver::HandWrittenCG;

  /// Müller's WCSPH: free-surface particles miss neighbours, so their summed density is below
  /// rho0; negative pressure would pull them into clumps (tensile instability). Clamping p >= 0
  /// avoids it. (δ-SPH keeps negative pressure: its continuity density has no deficit at the
  /// surface, and Monaghan's tensile correction keeps stretched particles from pairing.)
  bool clampNegativePressure = true;
  int threads = 0; // OpenMP threads; 0 = the OpenMP default

  /// The kernel that measures density for the chosen pressure solver (its registry entry's).
  DensityKernel densityKernel() const;
  bool anyPeriodic() const { return periodic[0] || periodic[1] || periodic[2]; }
  /// The walls whose images carry the no-slip velocity (all false unless wallFriction is NoSlip).
  std::array<bool, 6> noSlipWalls() const
  {
    std::array<bool, 6> walls = {};
    if (wallFriction == WallFriction::NoSlip)
    {
      walls = frictionWalls;
    }
    return walls;
  }
  /// Empty when usable, else a sentence naming the first bad parameter.
  std::string validate() const;
};

/// Mass that makes a particle inside a cubic lattice of the given spacing have exactly rest density
/// when density is summed with the given kernel of radius h (the plain rho0 * spacing^3 is off by a
/// few percent for h = 2 spacings, which would make a block at rest expand or shrink at t = 0).
float latticeParticleMass(float spacing, float smoothingLength, float restDensity,
                          DensityKernel kernel = DensityKernel::Poly6);

/// The spacing of the cubic lattice on which particles of this mass have rest density with the
/// given kernel (the inverse of latticeParticleMass).
float latticeSpacingForMass(float particleMass, float smoothingLength, float restDensity, DensityKernel kernel);

/// 1 / C, where C = -sum_j V (z_i - z_j) dW/dz over a rest lattice (V the particle volume) is what
/// the discrete SPH gradient returns for the linear field z; exactly 1 for a continuous kernel, but
/// 1.02 for the cubic spline at h = 2 spacings. Scaling pressure forces by it makes the discrete
/// gradient of a linear pressure (hydrostatics) exact on the rest lattice.
float latticeGradientCorrection(float spacing, float smoothingLength, DensityKernel kernel);

/// 1 / C, where C is what the viscous operator 2 (d + 2) sum_j V (v_ij . x_ij) / (r^2 + eta^2)
/// grad W_ij (Monaghan 2005) returns for a shear flow of unit Laplacian on the rest lattice: the
/// operator is consistent in the continuum but, with the few neighbours of h = 2 spacings, 0.7 to
/// 0.9 of the Laplacian; scaling the viscous term by it makes a resolved shear flow decay at the
/// fluid's viscosity. spikyGradient: the gradient of Müller's spiky kernel (with poly6 volumes).
float latticeLaplacianCorrection(float spacing, float smoothingLength, DensityKernel kernel,
                                 bool spikyGradient = false);

/// The same for Morris et al.'s (1997) operator 2 sum_j V x_ij . grad W_ij / (r^2 + eta^2) v_ij (δ-SPH's
/// laminar term). Its error on a lattice is the same for every direction of shear (its second
/// moment is isotropic on a cubic lattice), so this correction, unlike the one above, suits
/// a disordered flow as well as a layered one: about 1.01 for Wendland C2 at 3 spacings (the
/// eta^2 of the pair closest in).
float latticeMorrisLaplacianCorrection(float spacing, float smoothingLength, DensityKernel kernel);

/// The same for Müller's pressure force: the spiky gradient with volumes from the poly6 density.
float latticeSpikyGradientCorrection(float spacing, float smoothingLength);
} // namespace parafluid::sph
