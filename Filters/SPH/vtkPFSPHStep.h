/**
 * @class vtkPFSPHStep
 * @brief Time-aware filter: advances particles with SPH (Müller's weakly compressible SPH or
 * Bender & Koschier's divergence-free SPH).
 *
 * Input 0 is the particle state at t0 (its first time step, or its only state). The optional input
 * 1 ("Boundary") is a surface the particles cannot cross (any vtkPolyData; polygons are
 * triangulated). The output offers the times t0 + k * OutputInterval, k = 0 .. NumberOfOutputs, and
 * produces the state at the requested one: the solver takes as many steps as the time-step control
 * needs and lands exactly on it. The last computed state is cached: moving forward in the animation
 * continues from it; moving back, or changing a property or an input, restarts from t0. Output
 * particles keep the input's order and arrays, with position, velocity, density, id and (when asked)
 * pressure, acceleration and neighbour_count updated.
 *
 * Zero-valued SmoothingLength / ParticleMass / DomainBounds mean "from the input's field data"
 * (smoothing_length, particle_spacing, domain_bounds, as the ParaFluid reader and the Particle
 * Block source provide).
 */
#ifndef vtkPFSPHStep_h
#define vtkPFSPHStep_h

#include "ParaFluidSPHFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class vtkAlgorithmOutput;

#include <memory>

class PARAFLUIDSPHFILTERS_EXPORT vtkPFSPHStep : public vtkPolyDataAlgorithm
{
public:
  static vtkPFSPHStep* New();
  vtkTypeMacro(vtkPFSPHStep, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Kernel support radius h [m]; 0 = the input's smoothing_length, else 2 particle spacings.
  vtkSetMacro(SmoothingLength, double);
  vtkGetMacro(SmoothingLength, double);
  /// rho0 [kg/m^3].
  vtkSetMacro(RestDensity, double);
  vtkGetMacro(RestDensity, double);
  /// k in p = k (rho - rho0) [m^2/s^2 = Pa m^3/kg]; sqrt(k) is the speed of sound.
  vtkSetMacro(GasStiffness, double);
  vtkGetMacro(GasStiffness, double);
  /// Müller's viscosity coefficient mu [Pa s].
  vtkSetMacro(Viscosity, double);
  vtkGetMacro(Viscosity, double);
  /// 0 = WCSPH (Müller's equation of state), 1 = DFSPH (divergence-free, incompressible).
  vtkSetClampMacro(PressureSolver, int, 0, 1);
  vtkGetMacro(PressureSolver, int);
  /// Surface tension sigma [N/m] (colour-field model); 0 skips the colour-field pass.
  vtkSetMacro(SurfaceTension, double);
  vtkGetMacro(SurfaceTension, double);
  /// Choose each step from the CFL, viscous and force conditions (else use TimeStep).
  vtkSetMacro(AdaptiveTimeStep, bool);
  vtkGetMacro(AdaptiveTimeStep, bool);
  vtkBooleanMacro(AdaptiveTimeStep, bool);
  /// lambda in dt <= lambda h / (c + v_max).
  vtkSetMacro(CFLNumber, double);
  vtkGetMacro(CFLNumber, double);
  /// Upper limit of the adaptive step [s].
  vtkSetMacro(MaxTimeStep, double);
  vtkGetMacro(MaxTimeStep, double);
  /// Fixed dt [s] when AdaptiveTimeStep is off.
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  /// Simulated time between two output times [s].
  vtkSetMacro(OutputInterval, double);
  vtkGetMacro(OutputInterval, double);
  /// DFSPH: mean density error the solver keeps below (fraction of rest density).
  vtkSetMacro(DensityTolerance, double);
  vtkGetMacro(DensityTolerance, double);
  /// DFSPH: iteration limit of each solve.
  vtkSetMacro(MaxPressureIterations, int);
  vtkGetMacro(MaxPressureIterations, int);
  /// Fraction of the normal velocity lost when a particle hits the Boundary mesh (0..1).
  vtkSetMacro(BoundaryDamping, double);
  vtkGetMacro(BoundaryDamping, double);
  /// Optional output arrays: computed (or copied) only when on.
  vtkSetMacro(OutputPressure, bool);
  vtkGetMacro(OutputPressure, bool);
  vtkSetMacro(OutputAcceleration, bool);
  vtkGetMacro(OutputAcceleration, bool);
  vtkSetMacro(OutputNeighbourCount, bool);
  vtkGetMacro(OutputNeighbourCount, bool);

  /// Connects the optional boundary surface (input port 1).
  void SetBoundaryConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// Number of output times after t0.
  vtkSetClampMacro(NumberOfOutputs, int, 0, 1000000);
  vtkGetMacro(NumberOfOutputs, int);
  /// [m/s^2]
  vtkSetVector3Macro(Gravity, double);
  vtkGetVector3Macro(Gravity, double);
  /// The box the fluid stays in [m]; all zero = the input's domain_bounds field data.
  vtkSetVector6Macro(DomainBounds, double);
  vtkGetVector6Macro(DomainBounds, double);
  /// [kg]; 0 = the mass that gives rest density on the input's particle_spacing lattice.
  vtkSetMacro(ParticleMass, double);
  vtkGetMacro(ParticleMass, double);
  /// Fraction of the normal velocity kept when a particle bounces off a wall (0..1).
  vtkSetClampMacro(WallRestitution, double, 0.0, 1.0);
  vtkGetMacro(WallRestitution, double);
  /// Tangential stress of the walls: 0 free-slip, 1 no-slip (through the viscosity), 2 the
  /// turbulent law of the wall with WallKinematicViscosity (see parafluid/SPHParameters.h).
  vtkSetClampMacro(WallFriction, int, 0, 2);
  vtkGetMacro(WallFriction, int);
  /// Which walls WallFriction acts on (xmin xmax ymin ymax zmin zmax; 1 = on, 0 = free-slip).
  vtkSetVector6Macro(FrictionWalls, int);
  vtkGetVector6Macro(FrictionWalls, int);
  /// [m^2/s] molecular kinematic viscosity for the law of the wall (water at 20 °C: 1e-6).
  vtkSetMacro(WallKinematicViscosity, double);
  vtkGetMacro(WallKinematicViscosity, double);

  /// Number of SPH steps taken by the last update (0 when it was served from the cache).
  vtkGetMacro(StepsTakenLastUpdate, vtkIdType);
  /// Mean over particles of max(rho - rho0, 0) / rho0 after the last step of the last update.
  vtkGetMacro(MeanDensityError, double);

protected:
  vtkPFSPHStep();
  ~vtkPFSPHStep() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFSPHStep(const vtkPFSPHStep&) = delete;
  void operator=(const vtkPFSPHStep&) = delete;

  double SmoothingLength = 0.0;
  double RestDensity = 1000.0;
  double GasStiffness = 1000.0;
  double Viscosity = 3.5;
  int PressureSolver = 0;
  double SurfaceTension = 0.0;
  bool AdaptiveTimeStep = true;
  double CFLNumber = 0.2;
  double MaxTimeStep = 0.005;
  double TimeStep = 2.0e-4;
  double OutputInterval = 0.01;
  double DensityTolerance = 0.001;
  int MaxPressureIterations = 100;
  double BoundaryDamping = 0.5;
  bool OutputPressure = true;
  bool OutputAcceleration = false;
  bool OutputNeighbourCount = false;
  int NumberOfOutputs = 100;
  double Gravity[3] = { 0.0, 0.0, -9.81 };
  double DomainBounds[6] = { 0, 0, 0, 0, 0, 0 };
  double ParticleMass = 0.0;
  double WallRestitution = 0.5;
  int WallFriction = 0;
  int FrictionWalls[6] = { 1, 1, 1, 1, 1, 1 };
  double WallKinematicViscosity = 1.0e-6;

  double StartTime = 0.0;
  bool InputHasTime = false;
  vtkIdType StepsTakenLastUpdate = 0;
  double MeanDensityError = 0.0;

  struct Cache;
  std::unique_ptr<Cache> Cached;
};

#endif
