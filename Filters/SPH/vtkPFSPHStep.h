/**
 * @class vtkPFSPHStep
 * @brief Time-aware filter: advances particles with Müller et al. (2003) weakly compressible SPH.
 *
 * The input is the state at t0 (its first time step, or its only state). The output offers the
 * times t0 + k * StepsPerOutput * TimeStep, k = 0 .. NumberOfOutputs, and produces the state at the
 * requested one. The last computed state is cached: moving forward in the animation continues from
 * it; moving back, or changing a property or the input, restarts from t0. Output particles keep the
 * input's order and arrays, with position, velocity, density, pressure, acceleration and id updated.
 *
 * Zero-valued SmoothingLength / ParticleMass / DomainBounds mean "from the input's field data"
 * (smoothing_length, particle_spacing, domain_bounds, as the ParaFluid reader and the Particle
 * Block source provide).
 */
#ifndef vtkPFSPHStep_h
#define vtkPFSPHStep_h

#include "ParaFluidSPHFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

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
  /// dt [s].
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  /// SPH steps between two output times.
  vtkSetClampMacro(StepsPerOutput, int, 1, 1000000);
  vtkGetMacro(StepsPerOutput, int);
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

  /// Number of SPH steps taken by the last update (0 when it was served from the cache).
  vtkGetMacro(StepsTakenLastUpdate, vtkIdType);

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
  double TimeStep = 2.0e-4;
  int StepsPerOutput = 50;
  int NumberOfOutputs = 100;
  double Gravity[3] = { 0.0, 0.0, -9.81 };
  double DomainBounds[6] = { 0, 0, 0, 0, 0, 0 };
  double ParticleMass = 0.0;
  double WallRestitution = 0.5;

  double StartTime = 0.0;
  bool InputHasTime = false;
  vtkIdType StepsTakenLastUpdate = 0;

  struct Cache;
  std::unique_ptr<Cache> Cached;
};

#endif
