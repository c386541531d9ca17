/**
 * @class vtkPFGerstnerOcean
 * @brief Source: the ocean surface as a sum of Gerstner waves at the requested time.
 *
 * A grid of rest points on the sea level is displaced by parafluid::ocean::GerstnerOcean (the
 * same model the Gerstner Ocean representation runs on the GPU). Waves come from a sea-state
 * preset or from the wave list. An optional input on port 1 (SetBathymetryConnection; port 0
 * is never used), Bathymetry, gives the sea floor: a 2D image
 * whose point scalars are the floor elevation [m], or a terrain surface (rasterised at
 * BathymetryResolution); over it waves shoal, refract and break. Without it the water has the
 * uniform WaterDepth (0: deep water).
 *
 * Output: quads with point normals, `jacobian` (of the horizontal map; <= 0 is a fold), `foam`
 * (0..1: breaking crests and squeezed surface) and, where the water has a bottom, `depth` [m].
 * Time-aware: time steps every 1 / FrameRate seconds over [0, Duration]; any time can be asked for.
 */
#pragma once

#include "ParaFluidOceanFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include "parafluid/ocean/SeaSettings.h"

#include "AssignIfChanged.h"

#include <vector>

class PARAFLUIDOCEANFILTERS_EXPORT vtkPFGerstnerOcean : public vtkPolyDataAlgorithm
{
public:
  static vtkPFGerstnerOcean* New();
  vtkTypeMacro(vtkPFGerstnerOcean, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The sea floor (port 1): a 2D image of floor elevations or a terrain surface.
  void SetBathymetryConnection(vtkAlgorithmOutput* output);

  enum SeaStates
  {
    CUSTOM = 0, // the wave list
    CALM = 1,
    SWELL = 2,
    STORM = 3
  };

  /// Lower-left corner (x, y) of the ocean patch [m].
  vtkSetVector2Macro(Origin, double);
  vtkGetVector2Macro(Origin, double);
  /// Extent of the patch in x and y [m].
  vtkSetVector2Macro(Size, double);
  vtkGetVector2Macro(Size, double);
  /// Grid points in x and y (at least 2 each).
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  /// Direction the wind blows towards [degrees, counter-clockwise from +x]; presets spread their
  /// waves about it.
  void SetWindDirection(double value) { this->SetSea(this->Sea.windDirection, value); }
  double GetWindDirection() const { return this->Sea.windDirection; }
  /// How far crests lean downwind, 0 to 0.5.
  void SetWindLean(double value) { this->SetSea(this->Sea.windLean, value); }
  double GetWindLean() const { return this->Sea.windLean; }
  /// Uniform water depth without a sea floor [m]; 0 means deep water.
  void SetWaterDepth(double value) { this->SetSea(this->Sea.waterDepth, value); }
  double GetWaterDepth() const { return this->Sea.waterDepth; }
  /// Cap on the summed horizontal steepness; 1 is where the surface folds.
  void SetMaxSteepness(double value) { this->SetSea(this->Sea.maxSteepness, value); }
  double GetMaxSteepness() const { return this->Sea.maxSteepness; }
  /// Wave height over depth at which waves break (0.78, McCowan).
  void SetBreakingDepthRatio(double value) { this->SetSea(this->Sea.breakingDepthRatio, value); }
  double GetBreakingDepthRatio() const { return this->Sea.breakingDepthRatio; }
  /// Breaking crest: raised by this fraction of its amplitude, tilted forward by BreakingLean
  /// [rad], thrown forward by BreakingShift amplitudes.
  void SetBreakingStretch(double value) { this->SetSea(this->Sea.breakingStretch, value); }
  double GetBreakingStretch() const { return this->Sea.breakingStretch; }
  void SetBreakingLean(double value) { this->SetSea(this->Sea.breakingLean, value); }
  double GetBreakingLean() const { return this->Sea.breakingLean; }
  void SetBreakingShift(double value) { this->SetSea(this->Sea.breakingShift, value); }
  double GetBreakingShift() const { return this->Sea.breakingShift; }
  /// Height of the still water surface [m].
  void SetSeaLevel(double value) { this->SetSea(this->Sea.seaLevel, value); }
  double GetSeaLevel() const { return this->Sea.seaLevel; }
  /// 0 (custom) uses the wave list; the presets 1 calm, 2 swell, 3 storm ignore it.
  void SetSeaState(int value) { this->SetSea(this->Sea.seaState, value < 0 ? 0 : (value > 3 ? 3 : value)); }
  int GetSeaState() const { return this->Sea.seaState; }
  /// Wave list: amplitude [m], wavelength [m], direction [degrees], steepness Q [0, 1], phase [rad].
  void SetWave(int index, double amplitude, double wavelength, double direction, double steepness, double phase);
  void RemoveAllWaves();
  int GetNumberOfWaves() const { return static_cast<int>(this->Sea.waves.size() / 5); }
  /// Raster resolution for a terrain-surface Bathymetry (points per side).
  void SetBathymetryResolution(int value)
  {
    this->SetSea(this->Sea.bathymetryResolution, value < 2 ? 2 : (value > 8192 ? 8192 : value));
  }
  int GetBathymetryResolution() const { return this->Sea.bathymetryResolution; }
  /// Time span advertised to the animation [s] and time steps per second.
  vtkSetMacro(Duration, double);
  vtkGetMacro(Duration, double);
  vtkSetMacro(FrameRate, double);
  vtkGetMacro(FrameRate, double);

protected:
  vtkPFGerstnerOcean();
  ~vtkPFGerstnerOcean() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFGerstnerOcean(const vtkPFGerstnerOcean&) = delete;
  void operator=(const vtkPFGerstnerOcean&) = delete;
  template<class Field, class Value>
  void SetSea(Field& field, Value value)
  {
    parafluid::vtk::assignIfChanged(this, field, value);
  }
  /// The sea, shared in form with the Gerstner Ocean representation (parafluid/ocean/SeaSettings.h).
  parafluid::ocean::SeaSettings Sea;

  double Origin[2] = { 0.0, 0.0 };
  double Size[2] = { 200.0, 200.0 };
  int Resolution[2] = { 256, 256 };
  double Duration = 20.0;
  double FrameRate = 30.0;
};
