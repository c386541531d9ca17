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
#ifndef vtkPFGerstnerOcean_h
#define vtkPFGerstnerOcean_h

#include "ParaFluidOceanFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

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
  /// Height of the still water surface [m].
  vtkSetMacro(SeaLevel, double);
  vtkGetMacro(SeaLevel, double);
  /// CUSTOM uses the wave list; the presets ignore it.
  vtkSetClampMacro(SeaState, int, CUSTOM, STORM);
  vtkGetMacro(SeaState, int);
  /// Wave list: amplitude [m], wavelength [m], direction [degrees], steepness Q [0, 1], phase [rad].
  void SetWave(int index, double amplitude, double wavelength, double direction, double steepness, double phase);
  void RemoveAllWaves();
  int GetNumberOfWaves() const { return static_cast<int>(this->Waves.size() / 5); }
  /// Direction the wind blows towards [degrees, counter-clockwise from +x]; presets spread their
  /// waves about it.
  vtkSetMacro(WindDirection, double);
  vtkGetMacro(WindDirection, double);
  /// How far crests lean downwind, 0 to 0.5.
  vtkSetMacro(WindLean, double);
  vtkGetMacro(WindLean, double);
  /// Uniform water depth without a Bathymetry input [m]; 0 means deep water.
  vtkSetMacro(WaterDepth, double);
  vtkGetMacro(WaterDepth, double);
  /// Cap on the summed horizontal steepness; 1 is where the surface folds.
  vtkSetMacro(MaxSteepness, double);
  vtkGetMacro(MaxSteepness, double);
  /// Wave height over depth at which waves break (0.78, McCowan).
  vtkSetMacro(BreakingDepthRatio, double);
  vtkGetMacro(BreakingDepthRatio, double);
  /// Breaking crest: raised by this fraction of its amplitude, tilted forward by BreakingLean
  /// [rad], thrown forward by BreakingShift amplitudes.
  vtkSetMacro(BreakingStretch, double);
  vtkGetMacro(BreakingStretch, double);
  vtkSetMacro(BreakingLean, double);
  vtkGetMacro(BreakingLean, double);
  vtkSetMacro(BreakingShift, double);
  vtkGetMacro(BreakingShift, double);
  /// Raster resolution for a terrain-surface Bathymetry (points per side).
  vtkSetClampMacro(BathymetryResolution, int, 2, 8192);
  vtkGetMacro(BathymetryResolution, int);
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

  double Origin[2] = { 0.0, 0.0 };
  double Size[2] = { 200.0, 200.0 };
  int Resolution[2] = { 256, 256 };
  double SeaLevel = 0.0;
  int SeaState = SWELL;
  std::vector<double> Waves; // five numbers per wave
  double WindDirection = 0.0;
  double WindLean = 0.2;
  double WaterDepth = 0.0;
  double MaxSteepness = 0.9;
  double BreakingDepthRatio = 0.78;
  double BreakingStretch = 0.6;
  double BreakingLean = 0.6;
  double BreakingShift = 0.8;
  int BathymetryResolution = 256;
  double Duration = 20.0;
  double FrameRate = 30.0;
};

#endif
