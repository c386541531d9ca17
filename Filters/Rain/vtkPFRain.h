/**
 * @class vtkPFRain
 * @brief Time-aware filter: rain over a terrain that becomes SPH runoff.
 *
 * Input: the terrain, a 2-D height image (the terrain contract: `elevation`, point or cell data) or
 * any surface (rasterised onto ImpactResolution nodes). Outputs, at the requested animation time:
 *  - port 0, drops: one vertex per drop in the air, with `velocity` [m/s], `diameter` [m] and
 *    `streak_length` [m] (speed x ExposureTime);
 *  - port 1, water: the SPH particles (the particle contract: velocity, density, id and the scene
 *    constants), empty while nothing has reached the ground or without Runoff;
 *  - port 2, splashes: one vertex per impact of the last SplashLifetime seconds, with `age` [s],
 *    `normal`, `slope` [deg], `impact_angle` [deg] and `on_water` (0/1).
 * The drops are stateless (parafluid/rain/RainField.h): any time is one evaluation per drop. The
 * runoff (parafluid/rain/Runoff.h) is simulated: moving forward continues from the cached state,
 * going back or changing a property restarts from t = 0. Runs on process 0 under MPI.
 */
#pragma once

#include "ParaFluidRainFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include "parafluid/rain/RainParameters.h"
#include "parafluid/rain/Runoff.h"

#include "AssignIfChanged.h"

#include <memory>
#include <string>

class PARAFLUIDRAINFILTERS_EXPORT vtkPFRain : public vtkPolyDataAlgorithm
{
public:
  static vtkPFRain* New();
  vtkTypeMacro(vtkPFRain, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// x0 x1 y0 y1 [m] of the precipitation area; all zero: the terrain's.
  void SetPrecipitationBounds(double x0, double x1, double y0, double y1);
  /// Height of the precipitation plane [m]; 0: the terrain's top plus its relief (at least 5 m).
  void SetPrecipitationHeight(double value) { this->Set(this->PrecipitationHeight, value); }
  void SetCells(int nx, int ny);
  /// Nodes per side a terrain surface is rasterised on (a height image is used as it is).
  void SetImpactResolution(int nx, int ny);
  void SetRainfallRate(double value) { this->Set(this->Rain.rainfallRate, value); }
  void SetDropsPerRealDrop(double value) { this->Set(this->Rain.dropsPerRealDrop, value); }
  void SetWindVelocity(double x, double y);
  void SetVelocityJitter(double value) { this->Set(this->Rain.velocityJitter, value); }
  void SetTerminalVelocity(int value) { this->Set(this->Rain.terminalVelocity, value != 0); }
  void SetInitialSpeed(double value) { this->Set(this->Rain.initialSpeed, value); }
  void SetSeed(int value) { this->Set(this->SeedValue, value); }
  void SetRainDuration(double value) { this->Set(this->Rain.duration, value); }
  /// [s]: streak_length = speed x ExposureTime.
  void SetExposureTime(double value) { this->Set(this->ExposureTime, value); }
  /// [s]: how long an impact stays in the splash output.
  void SetSplashLifetime(double value) { this->Set(this->SplashLifetime, value); }

  /// Simulate the runoff (off: drops and splashes only).
  void SetRunoff(int value) { this->Set(this->SimulateRunoff, value != 0); }
  void SetParticleSpacing(double value) { this->Set(this->Water.particleSpacing, value); }
  void SetConserveVolume(int value) { this->Set(this->Water.conserveVolume, value != 0); }
  void SetRainScale(int value) { this->Set(this->Water.rainScale, value); }
  void SetSPHEvery(int value) { this->Set(this->Water.sphEvery, value); }
  void SetRainTimeStep(double value) { this->Set(this->Water.rainStep, value); }
  void SetInfiltration(double value) { this->Set(this->Water.infiltration, value); }
  void SetMaxParticles(int value) { this->Set(this->MaxParticlesValue, value); }
  /// SPH Step's solver settings (parafluid/sph/SPHParameters.h).
  void SetPressureSolver(int solver);
  /// Where the runoff's SPH runs, as SPH Step's Backend: 0 Automatic, 1 CPU, 2 CUDA.
  void SetBackend(int backend);
  void SetKinematicViscosity(double value) { this->Set(this->Water.sph.kinematicViscosity, static_cast<float>(value)); }
  void SetSurfaceTension(double value) { this->Set(this->Water.sph.surfaceTension, static_cast<float>(value)); }
  void SetCFLNumber(double value) { this->Set(this->Water.sph.cflNumber, static_cast<float>(value)); }
  void SetBoundaryDamping(double value) { this->Set(this->Water.sph.boundaryDamping, static_cast<float>(value)); }
  void SetSoundSpeed(double value) { this->Set(this->Water.sph.soundSpeed, static_cast<float>(value)); }
  void SetWallFriction(int friction);
  void SetDensityTolerance(double value) { this->Set(this->Water.sph.densityTolerance, static_cast<float>(value)); }

  vtkSetMacro(OutputInterval, double);
  vtkGetMacro(OutputInterval, double);
  vtkSetMacro(NumberOfOutputs, int);
  vtkGetMacro(NumberOfOutputs, int);

  /// After an update: drops drawn, and the volumes [m^3] of rain fallen, water in the SPH, and
  /// infiltrated.
  vtkGetMacro(DropCount, vtkIdType);
  vtkGetMacro(FallenVolume, double);
  vtkGetMacro(WaterVolume, double);
  vtkGetMacro(InfiltratedVolume, double);

protected:
  vtkPFRain();
  ~vtkPFRain() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFRain(const vtkPFRain&) = delete;
  void operator=(const vtkPFRain&) = delete;

  template<class Field, class Value>
  void Set(Field& field, Value value)
  {
    parafluid::vtk::assignIfChanged(this, field, value);
  }
  /// The memory the ground of `nodes` samples (and its runoff) needs fits the budget; else an
  /// error naming `property` and the bytes.
  bool GroundFits(double nodes, const char* property);
  void ReportError(const std::string& message);
  /// The ground from the input; null after an error.
  std::shared_ptr<const parafluid::HeightField> ReadGround(vtkDataObject* input);
  /// The rain's parameters with the automatic values resolved from the ground.
  bool Resolve(const parafluid::HeightField& ground, parafluid::rain::RainParameters& rain);
  void WriteDrops(const parafluid::rain::RainField& rain, const std::vector<float>* water, double t,
                  vtkPolyData* output);
  void WriteWater(double t, vtkPolyData* output);
  void WriteSplashes(const parafluid::rain::RainField& rain, const std::vector<float>* water, double t,
                     vtkPolyData* output);

  parafluid::rain::RainParameters Rain;
  parafluid::rain::RunoffParameters Water;
  double PrecipitationBoundsValue[4] = { 0, 0, 0, 0 };
  double PrecipitationHeight = 0.0;
  int ImpactResolution[2] = { 256, 256 };
  int SeedValue = 1;
  int MaxParticlesValue = 4000000;
  double ExposureTime = 1.0 / 60.0;
  double SplashLifetime = 0.1;
  bool SimulateRunoff = true;
  double OutputInterval = 1.0 / 30.0;
  int NumberOfOutputs = 300;

  vtkIdType DropCount = 0;
  double FallenVolume = 0.0, WaterVolume = 0.0, InfiltratedVolume = 0.0;

  struct Cache;
  std::unique_ptr<Cache> Cached;
};
