#include "parafluid/sph/SPHParameterTable.h"

namespace parafluid::sph
{
const std::vector<ParameterDeclaration>& sphParameterTable()
{
  using P = SPHParameters;
  static const std::vector<ParameterDeclaration> table = {
    declare<P>("SmoothingLength", "Smoothing Length", "m", 1e-9, 1e3, &P::smoothingLength,
               "the kernel's support radius h", "from the input's smoothing_length, else the solver's default support"),
    declare<P>("RestDensity", "Rest Density", "kg/m^3", 1e-6, 1e6, &P::restDensity, "the fluid's density at rest"),
    declare<P>("KinematicViscosity", "Kinematic Viscosity", "m^2/s", 0.0, 1e3, &P::kinematicViscosity,
               "the fluid's physical viscosity (water at 20 °C: 1e-6)"),
    declare<P>("GasStiffness", "Gas Stiffness", "m^2/s^2", 0.0, 1e12, &P::gasStiffness,
               "k in Müller's p = k (rho - rho0); its root is the sound speed (WCSPH)"),
    declare<P>("Viscosity", "Viscosity", "Pa s", 0.0, 1e9, &P::viscosity,
               "the extra viscosity of Müller's seed method (its paper: 3.5)"),
    declare<P>("SoundSpeed", "Sound Speed", "m/s", 0.0, 1e5, &P::soundSpeed,
               "c0 of δ-SPH's equation of state; 0: ten times the free-fall speed over the fluid's height"),
    declare<P>("ArtificialViscosity", "Artificial Viscosity", "", 0.0, 10.0, &P::artificialViscosity,
               "Monaghan's alpha, δ-SPH's only numerical viscosity"),
    declare<P>("DensityDiffusion", "Density Diffusion", "", 0.0, 1.0, &P::densityDiffusion,
               "δ-SPH's density-diffusion coefficient delta"),
    declare<P>("SurfaceTension", "Surface Tension", "N/m", 0.0, 1e3, &P::surfaceTension,
               "sigma (water-air: 0.0728); 0 skips the pass"),
    coreOnly(declare<P>("SurfaceThreshold", "Surface Threshold", "", 0.0, 1e3, &P::surfaceThreshold,
                        "a particle is on the surface where the colour field's gradient exceeds this over h")),
    declare<P>("CFLNumber", "CFL Number", "", 0.001, 2.0, &P::cflNumber,
               "lambda of the CFL step lambda h / (c + v_max), relative to the support radius"),
    declare<P>("MaxTimeStep", "Max Time Step", "s", 1e-9, 1e3, &P::maxTimeStep, "the longest adaptive step"),
    declare<P>("TimeStep", "Time Step", "s", 1e-9, 1e3, &P::timeStep, "the step when AdaptiveTimeStep is off"),
    declare<P>("DensityTolerance", "Density Tolerance", "", 1e-6, 0.5, &P::densityTolerance,
               "DFSPH: the mean compression its density solve stops at, a fraction of rest density"),
    coreOnly(declare<P>("DivergenceTolerance", "Divergence Tolerance", "", 1e-6, 0.5, &P::divergenceTolerance,
                        "DFSPH: the mean dt (D rho / D t) / rho0 its divergence solve stops at")),
    declare<P>("MaxPressureIterations", "Max Pressure Iterations", "", 1, 100000, &P::maxPressureIterations,
               "DFSPH: the most iterations of each solve in a step"),
    coreOnly(declare<P>("ViscosityTolerance", "Viscosity Tolerance", "", 1e-9, 0.5, &P::viscosityTolerance,
                        "DFSPH: the implicit viscosity's residual relative to its right-hand side")),
    declare<P>("ParticleMass", "Particle Mass", "kg", 1e-30, 1e6, &P::particleMass, "the mass m of every particle",
               "from the input's particle_spacing, so a lattice of it is at rest density"),
    declare<P>("WallRestitution", "Wall Restitution", "", 0.0, 1.0, &P::wallRestitution,
               "the fraction of the normal velocity kept when bouncing off a box wall"),
    declare<P>("WallKinematicViscosity", "Wall Kinematic Viscosity", "m^2/s", 1e-9, 1.0, &P::wallKinematicViscosity,
               "the molecular viscosity of the law of the wall (WallFriction LogLaw)"),
    declare<P>("BoundaryDamping", "Boundary Damping", "", 0.0, 1.0, &P::boundaryDamping,
               "the fraction of the normal velocity lost when bouncing off the Boundary surface"),
  };
  return table;
}

const ParameterDeclaration* findSPHParameter(std::string_view name)
{
  for (const ParameterDeclaration& d : sphParameterTable())
  {
    if (name == d.name)
    {
      return &d;
    }
  }
  return nullptr;
}

std::string checkParameter(const ParameterDeclaration& d, double value, bool zeroAllowed)
{
  return checkNumber(d.name, d.unit, d.minimum, d.maximum, value, zeroAllowed, d.zeroMeans);
}

std::string checkParameters(const SPHParameters& p, std::initializer_list<std::string_view> names,
                            std::initializer_list<std::string_view> zeroAllowed)
{
  return checkDeclared(sphParameterTable(), p, names, zeroAllowed);
}

std::string checkParameterRanges(const SPHParameters& p, std::initializer_list<std::string_view> zeroAllowed)
{
  return checkDeclared(sphParameterTable(), p, {}, zeroAllowed);
}

std::string parameterTableMarkdown()
{
  return markdownTable(sphParameterTable());
}
} // namespace parafluid::sph
