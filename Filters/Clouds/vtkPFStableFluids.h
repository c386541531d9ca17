/**
 * @class vtkPFStableFluids
 * @brief Source: clouds and smoke on a grid (Stam's stable fluids), stepped to the animation time.
 *
 * A box of cubic cells (Bounds, at most Resolution cells per axis) holds air whose velocity,
 * density (cloud water or smoke) and temperature are stepped by parafluid::clouds::StableFluids:
 * semi-Lagrangian advection (optionally MacCormack), buoyancy, vorticity confinement, implicit
 * diffusion and a projection to zero divergence by multigrid-preconditioned CG. Density and heat
 * come from an emitter box, from the points of an optional input dataset (particles, a terrain's
 * valleys; with point scalars only the points whose scalar is above 0), and from an optional
 * procedural start (cumulus shapes from 3-D noise).
 *
 * Output: vtkImageData with point data at the cells' centres: `density`, `temperature` [K],
 * `velocity` [m/s] and, with OutputDivergence, `divergence` [1/s].
 * Time-aware: outputs every OutputInterval seconds; going forward continues from the cached
 * state, going back (or changing a property or the input) starts again from the beginning.
 */
#pragma once

#include "ParaFluidCloudsFiltersModule.h"
#include "vtkImageAlgorithm.h"

#include "AssignIfChanged.h"
#include "EnumerationChoice.h"
#include "parafluid/clouds/StableFluidsParameterTable.h"

#include <memory>

class PARAFLUIDCLOUDSFILTERS_EXPORT vtkPFStableFluids : public vtkImageAlgorithm
{
public:
  static vtkPFStableFluids* New();
  vtkTypeMacro(vtkPFStableFluids, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Optional sources (port 1; port 0 is never used, so that pvpython does not connect the
  /// active pipeline object as sources): the points of any dataset inject like the emitter.
  void SetSourcesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// The box [m]: xmin, xmax, ymin, ymax, zmin, zmax.
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  /// Cells per axis at most; cells are cubes, so a shorter axis gets fewer.
  vtkSetVector3Macro(Resolution, int);
  vtkGetVector3Macro(Resolution, int);
  /// Simulation step [s]; an output interval is covered in equal steps no longer than this.
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  vtkSetMacro(OutputInterval, double);
  vtkGetMacro(OutputInterval, double);
  vtkSetMacro(NumberOfOutputs, int);
  vtkGetMacro(NumberOfOutputs, int);

  vtkSetMacro(MacCormack, bool);
  vtkGetMacro(MacCormack, bool);
  vtkSetMacro(Conservative, bool);
  vtkGetMacro(Conservative, bool);
  /// Kinematic viscosity of the air and diffusivity of density and heat [m^2/s] (0: none).
  void SetViscosity(double value) { parafluid::vtk::assignIfChanged(this, this->Parameters.viscosity, value); }
  double GetViscosity() const { return this->Parameters.viscosity; }
  void SetDiffusivity(double value) { parafluid::vtk::assignIfChanged(this, this->Parameters.diffusivity, value); }
  double GetDiffusivity() const { return this->Parameters.diffusivity; }
  /// Buoyancy: density weighs down [m/s^2 per unit density], heat lifts [m/s^2 per K].
  void SetBuoyancyDensity(double value)
  {
    parafluid::vtk::assignIfChanged(this, this->Parameters.buoyancyDensity, value);
  }
  double GetBuoyancyDensity() const { return this->Parameters.buoyancyDensity; }
  void SetBuoyancyHeat(double value) { parafluid::vtk::assignIfChanged(this, this->Parameters.buoyancyHeat, value); }
  double GetBuoyancyHeat() const { return this->Parameters.buoyancyHeat; }
  void SetAmbientTemperature(double value)
  {
    parafluid::vtk::assignIfChanged(this, this->Parameters.ambientTemperature, value);
  }
  double GetAmbientTemperature() const { return this->Parameters.ambientTemperature; }
  /// Vorticity confinement strength epsilon (0: off).
  void SetVorticity(double value) { parafluid::vtk::assignIfChanged(this, this->Parameters.vorticity, value); }
  double GetVorticity() const { return this->Parameters.vorticity; }
  /// Open faces (1) let air and smoke through; closed (0) are walls. xmin, xmax, ..., zmax.
  vtkSetVector6Macro(OpenFaces, int);
  vtkGetVector6Macro(OpenFaces, int);

  vtkSetMacro(Emitter, bool);
  vtkGetMacro(Emitter, bool);
  vtkSetVector6Macro(EmitterBox, double);
  vtkGetVector6Macro(EmitterBox, double);
  void SetEmitterDensity(double value)
  {
    parafluid::vtk::assignIfChanged(this, this->Parameters.emitterDensity, value);
  }
  double GetEmitterDensity() const { return this->Parameters.emitterDensity; }
  /// [K] above ambient.
  void SetEmitterTemperature(double value)
  {
    parafluid::vtk::assignIfChanged(this, this->Parameters.emitterTemperature, value);
  }
  double GetEmitterTemperature() const { return this->Parameters.emitterTemperature; }
  /// Upward speed the emitter blows [m/s].
  void SetEmitterSpeed(double value) { parafluid::vtk::assignIfChanged(this, this->Parameters.emitterSpeed, value); }
  double GetEmitterSpeed() const { return this->Parameters.emitterSpeed; }

  /// Procedural start: cumulus shapes covering CloudCoverage of the sky.
  vtkSetMacro(ProceduralClouds, bool);
  vtkGetMacro(ProceduralClouds, bool);
  vtkSetMacro(CloudCoverage, double);
  vtkGetMacro(CloudCoverage, double);
  /// Size of the cloud cells [m].
  vtkSetMacro(CloudFeatureSize, double);
  vtkGetMacro(CloudFeatureSize, double);
  vtkSetMacro(CloudSeed, int);
  vtkGetMacro(CloudSeed, int);

  /// Relative residual of the pressure solve, and its preconditioner (0 multigrid, 1 Jacobi).
  void SetProjectionTolerance(double value)
  {
    parafluid::vtk::assignIfChanged(this, this->Parameters.projectionTolerance, value);
  }
  double GetProjectionTolerance() const { return this->Parameters.projectionTolerance; }
  void SetPreconditioner(int value)
  {
    if (parafluid::vtk::isChoice(this, "Preconditioner", value, { "Multigrid", "Jacobi" }, this->Preconditioner))
    {
      parafluid::vtk::assignIfChanged(this, this->Preconditioner, value);
    }
  }
  vtkGetMacro(Preconditioner, int);
  vtkSetMacro(OutputDivergence, bool);
  vtkGetMacro(OutputDivergence, bool);

  /// Steps and pressure-solve iterations of the last output (for tests and benchmarks).
  long long GetLastStepCount() const { return this->LastSteps; }
  int GetLastProjectionIterations() const { return this->LastIterations; }

protected:
  vtkPFStableFluids();
  ~vtkPFStableFluids() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFStableFluids(const vtkPFStableFluids&) = delete;
  void operator=(const vtkPFStableFluids&) = delete;
  struct Cache;
  std::unique_ptr<Cache> Cached;
  /// The grid the properties ask for: cells per axis, cell size [m]; false with an error.
  bool GridShape(int cells[3], double& h);
  /// The other properties within their XML domains; false with an error naming the first that is not.
  bool CheckParameters();
  /// Steps the run on to output `target`: 1, or -1 when aborted, 0 with an error (the run is
  /// dropped in both).
  int AdvanceTo(long long target, double cellCount);
  /// More steps than this in one output interval is an error, not a wait.
  static constexpr double kMaxStepsPerOutput = 10000.0;

  // The declared parameters (StableFluidsParameterTable.h); the grid and the flags are set apart.
  parafluid::clouds::StableFluidsParameters Parameters = parafluid::clouds::sourceDefaults();
  double Bounds[6] = { 0.0, 2.0, 0.0, 2.0, 0.0, 2.0 };
  int Resolution[3] = { 64, 64, 64 };
  double TimeStep = 0.02;
  double OutputInterval = 0.1;
  int NumberOfOutputs = 100;
  bool MacCormack = true;
  bool Conservative = true;
  int OpenFaces[6] = { 0, 0, 0, 0, 0, 1 };
  bool Emitter = true;
  double EmitterBox[6] = { 0.8, 1.2, 0.8, 1.2, 0.0, 0.2 };
  bool ProceduralClouds = false;
  double CloudCoverage = 0.4;
  double CloudFeatureSize = 1.0;
  int CloudSeed = 1;
  int Preconditioner = 0;
  bool OutputDivergence = false;
  long long LastSteps = 0;
  int LastIterations = 0;
};
