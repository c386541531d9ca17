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
 *
 * Under MPI (pvbatch, pvserver) with δ-SPH or WCSPH on the CPU, the run is distributed: each
 * process steps the particles in its slab of the domain (DistributedSimulation.h) and outputs
 * them, in id order, with the simulated arrays only. Other solvers and the CUDA backend gather
 * the particles on process 0 and run there.
 */
#pragma once

#include "ParaFluidSPHFiltersModule.h"
#include "vtkPFParticleAlgorithm.h"

#include "parafluid/sph/SPHParameters.h"

#include "AssignIfChanged.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>

class vtkAlgorithmOutput;
class vtkFieldData;
class vtkPointSet;

namespace parafluid
{
class Communicator;
}

class PARAFLUIDSPHFILTERS_EXPORT vtkPFSPHStep : public vtkPFParticleAlgorithm
{
public:
  static vtkPFSPHStep* New();
  vtkTypeMacro(vtkPFSPHStep, vtkPFParticleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The solver's parameters are fields of Parameters (parafluid/sph/SPHParameters.h, SI units);
  // each setter writes its field. Zero SmoothingLength, ParticleMass and DomainBounds mean "from
  // the input's field data" and are resolved when the simulation starts.

  /// Kernel support radius h [m]; 0 = the input's smoothing_length, else 2 particle spacings.
  void SetSmoothingLength(double value) { this->SetParameter(this->Parameters.smoothingLength, value); }
  double GetSmoothingLength() const { return this->Parameters.smoothingLength; }
  /// rho0 [kg/m^3].
  void SetRestDensity(double value) { this->SetParameter(this->Parameters.restDensity, value); }
  double GetRestDensity() const { return this->Parameters.restDensity; }
  /// k in p = k (rho - rho0) [m^2/s^2 = Pa m^3/kg]; sqrt(k) is the speed of sound.
  void SetGasStiffness(double value) { this->SetParameter(this->Parameters.gasStiffness, value); }
  double GetGasStiffness() const { return this->Parameters.gasStiffness; }
  /// Müller's viscosity coefficient mu [Pa s].
  void SetViscosity(double value) { this->SetParameter(this->Parameters.viscosity, value); }
  double GetViscosity() const { return this->Parameters.viscosity; }
  /// 0 = WCSPH (Müller's equation of state), 1 = DFSPH (divergence-free, incompressible).
  void SetPressureSolver(int solver);
  int GetPressureSolver() const;
  /// Surface tension sigma [N/m] (colour-field model); 0 skips the colour-field pass.
  void SetSurfaceTension(double value) { this->SetParameter(this->Parameters.surfaceTension, value); }
  double GetSurfaceTension() const { return this->Parameters.surfaceTension; }

  /// 0: Müller's colour field, 1: Akinci et al. 2013, cohesion and curvature (the default), 2: their
  /// cohesion alone.
  void SetSurfaceTensionModel(int model);
  int GetSurfaceTensionModel() const { return static_cast<int>(this->Parameters.surfaceTensionModel); }

  /// The fluid's kinematic viscosity nu [m^2/s] (water: 1e-6), every solver.
  void SetKinematicViscosity(double value) { this->SetParameter(this->Parameters.kinematicViscosity, value); }
  double GetKinematicViscosity() const { return this->Parameters.kinematicViscosity; }

  /// δ-SPH: Monaghan's artificial viscosity alpha, the density diffusion delta, the speed of sound
  /// c0 [m/s] (0: automatic).
  void SetArtificialViscosity(double value) { this->SetParameter(this->Parameters.artificialViscosity, value); }
  double GetArtificialViscosity() const { return this->Parameters.artificialViscosity; }
  void SetDensityDiffusion(double value) { this->SetParameter(this->Parameters.densityDiffusion, value); }
  double GetDensityDiffusion() const { return this->Parameters.densityDiffusion; }
  void SetSoundSpeed(double value) { this->SetParameter(this->Parameters.soundSpeed, value); }
  double GetSoundSpeed() const { return this->Parameters.soundSpeed; }
  /// δ-SPH: shift interior particles towards uniform spacing after each move (Lind et al. 2012,
  /// with the δ+-SPH coefficient of Sun et al. 2017), for flows that stretch the particle
  /// distribution (vortices).
  void SetParticleShifting(bool value) { this->SetParameter(this->Parameters.particleShifting, value); }
  bool GetParticleShifting() const { return this->Parameters.particleShifting; }
  /// δ-SPH: correct the pressure gradient of particles with a full neighbourhood (on by default).
  void SetGradientCorrection(bool value) { this->SetParameter(this->Parameters.gradientCorrection, value); }
  bool GetGradientCorrection() const { return this->Parameters.gradientCorrection; }
  /// δ-SPH: take the smooth part out of the pressure force's 2 p_i term in full neighbourhoods,
  /// so the particle lattice has no long-wave shear stiffness under pressure (on by default).
  void SetPushHighPass(bool value) { this->SetParameter(this->Parameters.pushHighPass, value); }
  bool GetPushHighPass() const { return this->Parameters.pushHighPass; }

  /// Periodic axes x, y, z (0 or 1): the pair of box faces of that axis wrap around.
  void SetPeriodicAxes(int x, int y, int z);
  /// Choose each step from the CFL, viscous and force conditions (else use TimeStep).
  void SetAdaptiveTimeStep(bool value) { this->SetParameter(this->Parameters.adaptiveTimeStep, value); }
  bool GetAdaptiveTimeStep() const { return this->Parameters.adaptiveTimeStep; }
  /// lambda in dt <= lambda h / (c + v_max).
  void SetCFLNumber(double value) { this->SetParameter(this->Parameters.cflNumber, value); }
  double GetCFLNumber() const { return this->Parameters.cflNumber; }
  /// Upper limit of the adaptive step [s].
  void SetMaxTimeStep(double value) { this->SetParameter(this->Parameters.maxTimeStep, value); }
  double GetMaxTimeStep() const { return this->Parameters.maxTimeStep; }
  /// Fixed dt [s] when AdaptiveTimeStep is off.
  void SetTimeStep(double value) { this->SetParameter(this->Parameters.timeStep, value); }
  double GetTimeStep() const { return this->Parameters.timeStep; }
  /// DFSPH: mean density error the solver keeps below (fraction of rest density).
  void SetDensityTolerance(double value) { this->SetParameter(this->Parameters.densityTolerance, value); }
  double GetDensityTolerance() const { return this->Parameters.densityTolerance; }
  /// DFSPH: iteration limit of each solve.
  void SetMaxPressureIterations(int value) { this->SetParameter(this->Parameters.maxPressureIterations, value); }
  int GetMaxPressureIterations() const { return this->Parameters.maxPressureIterations; }
  /// Fraction of the normal velocity lost when a particle hits the Boundary mesh (0..1).
  void SetBoundaryDamping(double value) { this->SetParameter(this->Parameters.boundaryDamping, value); }
  double GetBoundaryDamping() const { return this->Parameters.boundaryDamping; }
  /// δ-SPH and DFSPH: the Boundary mesh is also a wall in the density and pressure sums (on by
  /// default); off, it only stops particles.
  void SetBoundaryWall(bool value) { this->SetParameter(this->Parameters.meshWallDensity, value); }
  bool GetBoundaryWall() const { return this->Parameters.meshWallDensity; }
  /// [m/s^2]
  void SetGravity(double x, double y, double z);
  /// The box the fluid stays in [m]; all zero = the input's domain_bounds field data.
  void SetDomainBounds(double x0, double x1, double y0, double y1, double z0, double z1);
  /// [kg]; 0 = the mass that gives rest density on the input's particle_spacing lattice.
  void SetParticleMass(double value) { this->SetParameter(this->Parameters.particleMass, value); }
  double GetParticleMass() const { return this->Parameters.particleMass; }
  /// Fraction of the normal velocity kept when a particle bounces off a wall (0..1).
  void SetWallRestitution(double value);
  double GetWallRestitution() const { return this->Parameters.wallRestitution; }
  /// Tangential stress of the walls: 0 free-slip, 1 no-slip (through the viscosity), 2 the
  /// turbulent law of the wall with WallKinematicViscosity (see parafluid/sph/SPHParameters.h).
  void SetWallFriction(int friction);
  int GetWallFriction() const { return static_cast<int>(this->Parameters.wallFriction); }
  /// Which walls WallFriction acts on (xmin xmax ymin ymax zmin zmax; 1 = on, 0 = free-slip).
  void SetFrictionWalls(int x0, int x1, int y0, int y1, int z0, int z1);
  /// [m^2/s] molecular kinematic viscosity for the law of the wall (water at 20 °C: 1e-6).
  void SetWallKinematicViscosity(double value) { this->SetParameter(this->Parameters.wallKinematicViscosity, value); }
  double GetWallKinematicViscosity() const { return this->Parameters.wallKinematicViscosity; }

  /// Where the simulation runs: 0 Automatic (the GPU when this build's CUDA backend is usable here
  /// and runs the scene, else the CPU; the output window says which and why), 1 CPU, 2 CUDA (an
  /// error, naming why, where it cannot run).
  void SetBackend(int backend);
  vtkGetMacro(Backend, int);
  /// The backend that runs the simulation ("CPU", "CUDA (NVIDIA H200)"; for Automatic on the CPU,
  /// why not the GPU); empty before the first update.
  const char* GetBackendUsed() const { return this->BackendUsed.c_str(); }

  /// Simulated time between two output times [s].
  vtkSetMacro(OutputInterval, double);
  vtkGetMacro(OutputInterval, double);
  /// Number of output times after t0.
  vtkSetClampMacro(NumberOfOutputs, int, 0, 1000000);
  vtkGetMacro(NumberOfOutputs, int);
  /// Optional output arrays: computed (or copied) only when on.
  vtkSetMacro(OutputPressure, bool);
  vtkGetMacro(OutputPressure, bool);
  vtkSetMacro(OutputAcceleration, bool);
  vtkGetMacro(OutputAcceleration, bool);
  vtkSetMacro(OutputNeighbourCount, bool);
  vtkGetMacro(OutputNeighbourCount, bool);

  /// Connects the optional boundary surface (input port 1).
  void SetBoundaryConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

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
  /// Under MPI, δ-SPH and WCSPH on the CPU run distributed: each process steps its own particles.
  bool WorksOnPieces() const override;
  int RequestParticles(const Particles& particles, vtkInformationVector** inputVector, vtkInformation* outInfo,
                       vtkPolyData* output) override;

private:
  vtkPFSPHStep(const vtkPFSPHStep&) = delete;
  void operator=(const vtkPFSPHStep&) = delete;

  template<class Field, class Value>
  void SetParameter(Field& field, Value value)
  {
    parafluid::vtk::assignIfChanged(this, field, value);
  }
  /// The parameters with the automatic values taken from the input's field data; false (after an
  /// error that names the property to set) when the input cannot supply them.
  bool ResolveParameters(vtkFieldData* fieldData, parafluid::sph::SPHParameters& resolved);
  /// A new simulation from the input particles and the optional boundary surface.
  /// Warns where the parameters ask for what the validation found unsound (Benchmarks README).
  void WarnOfUnvalidatedSurfaceTension(const parafluid::sph::SPHParameters& p);
  /// The Boundary input as a surface (a height image becomes its warped surface); false after an
  /// error. Null without one.
  bool ReadBoundary(vtkDataObject* boundaryData, vtkSmartPointer<vtkPolyData>& boundary);
  bool StartSimulation(vtkPointSet* input, vtkPolyData* boundary);
  /// StartSimulation of a distributed run, on every process with its own piece; false on all when
  /// one process could not start.
  bool StartDistributed(vtkPointSet* piece, vtkPolyData* boundary, bool boundaryRead);
  /// Steps the cached simulation to output `target`, one output interval at a time: 1 when there,
  /// 0 after an error, -1 when the user aborted (the simulation is dropped either way).
  int AdvanceTo(long long target);
  /// The simulated state into `output`, with the input's other arrays and the scene constants.
  void WriteOutput(vtkPointSet* input, long long target, vtkPolyData* output);

  parafluid::sph::SPHParameters Parameters;
  int Backend = 0;
  std::string BackendUsed;
  double OutputInterval = 0.01;
  int NumberOfOutputs = 100;
  bool OutputPressure = true;
  bool OutputAcceleration = false;
  bool OutputNeighbourCount = false;

  double StartTime = 0.0;
  bool InputHasTime = false;
  vtkIdType StepsTakenLastUpdate = 0;
  double MeanDensityError = 0.0;

  // The processes of a distributed run; declared before the cache, whose run uses it to the end.
  std::unique_ptr<parafluid::Communicator> Processes;
  struct Cache;
  std::unique_ptr<Cache> Cached;
};
