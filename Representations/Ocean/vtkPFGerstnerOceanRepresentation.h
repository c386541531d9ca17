/**
 * @class vtkPFGerstnerOceanRepresentation
 * @brief Renders a flat surface (a Plane, a grid) as a moving ocean, on the GPU.
 *
 * A surface representation whose vertex shader displaces every vertex with the Gerstner wave
 * model of parafluid::ocean::GerstnerOcean (same parameters as the Gerstner Ocean source; the
 * GLSL in GerstnerOceanWaves.glsl mirrors the C++), at the view's time. The fragment shader
 * re-evaluates the waves' derivatives per pixel for the normal, adds capillary ripples from a
 * procedurally generated, tileable normal map (two scrolling samples at unrelated scales),
 * reflects the environment (a cube map from six images, or a procedural sky with a sun) with
 * Schlick's Fresnel term (R0 = 0.02), colours the water from shallow to deep by depth, adds sun
 * specular and foam, and tone-maps the linear HDR result with a fixed or automatic exposure.
 *
 * The surface should lie at the sea's rest height. With BathymetryArray naming a point array of
 * floor elevations [m] on the input (for instance from Resample With Dataset on a terrain), waves
 * shoal, refract and break over it: the floor and each wave's phase field are uploaded as float
 * textures (up to 8 waves then; 16 in deep or uniform water).
 */
#pragma once

#include "ParaFluidOceanRepresentationsModule.h"
#include "SetParameterMacros.h"
#include "vtkGeometryRepresentationWithFaces.h"

#include "parafluid/ocean/SeaSettings.h"

#include "AssignIfChanged.h"

#include <memory>
#include <string>
#include <vector>

class PARAFLUIDOCEANREPRESENTATIONS_EXPORT vtkPFGerstnerOceanRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkPFGerstnerOceanRepresentation* New();
  vtkTypeMacro(vtkPFGerstnerOceanRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

  //@{
  /// The wave model: as on the Gerstner Ocean source (see vtkPFGerstnerOcean).
  void SetSeaState(int value) { this->SetSea(this->Sea.seaState, value < 0 ? 0 : (value > 3 ? 3 : value)); }
  int GetSeaState() const { return this->Sea.seaState; }
  void SetWave(int index, double amplitude, double wavelength, double direction, double steepness, double phase);
  void RemoveAllWaves();
  void SetWindDirection(double value) { this->SetSea(this->Sea.windDirection, value); }
  double GetWindDirection() const { return this->Sea.windDirection; }
  void SetWindLean(double value) { this->SetSea(this->Sea.windLean, value); }
  double GetWindLean() const { return this->Sea.windLean; }
  void SetWaterDepth(double value) { this->SetSea(this->Sea.waterDepth, value); }
  double GetWaterDepth() const { return this->Sea.waterDepth; }
  void SetMaxSteepness(double value) { this->SetSea(this->Sea.maxSteepness, value); }
  double GetMaxSteepness() const { return this->Sea.maxSteepness; }
  void SetBreakingDepthRatio(double value) { this->SetSea(this->Sea.breakingDepthRatio, value); }
  void SetBreakingStretch(double value) { this->SetSea(this->Sea.breakingStretch, value); }
  void SetBreakingLean(double value) { this->SetSea(this->Sea.breakingLean, value); }
  void SetBreakingShift(double value) { this->SetSea(this->Sea.breakingShift, value); }
  void SetSeaLevel(double value) { this->SetSea(this->Sea.seaLevel, value); }
  double GetSeaLevel() const { return this->Sea.seaLevel; }
  /// Point array of floor elevations [m] on the input; empty: no bathymetry.
  void SetBathymetryArray(const char* name);
  void SetBathymetryResolution(int value)
  {
    this->SetSea(this->Sea.bathymetryResolution, value < 2 ? 2 : (value > 4096 ? 4096 : value));
  }
  //@}

  //@{
  /// Shading. ShadingMode 0: realistic; 1: one solid colour (SolidColor), for checking shapes;
  /// 2: the wave normal as a colour (0.5 + 0.5 n).
  vtkPFSetClampMacro(ShadingMode, int, 0, 2);
  vtkPFSetFiniteVector3Macro(SolidColor, double);
  vtkPFSetClampVector3Macro(DeepColor, double, 0.0, 1.0);
  vtkPFSetClampVector3Macro(ShallowColor, double, 0.0, 1.0);
  /// Metres of water over which the colour goes from shallow to deep.
  vtkPFSetFiniteMacro(ColorDepth, double);
  vtkPFSetClampVector3Macro(FoamColor, double, 0.0, 1.0);
  vtkPFSetFiniteMacro(FoamAmount, double);
  /// Sun elevation and azimuth [degrees], colour and intensity (linear radiance).
  vtkPFSetFiniteMacro(SunElevation, double);
  vtkPFSetFiniteMacro(SunAzimuth, double);
  vtkPFSetClampVector3Macro(SunColor, double, 0.0, 1.0);
  vtkPFSetClampMacro(SunIntensity, double, 0.0, 1000.0);
  vtkPFSetFiniteMacro(Shininess, double);
  /// Procedural sky (when no environment images are given).
  vtkPFSetClampVector3Macro(HorizonColor, double, 0.0, 1.0);
  vtkPFSetClampVector3Macro(ZenithColor, double, 0.0, 1.0);
  /// Six cube map faces (+X, -X, +Y, -Y, +Z, -Z; +Y of the images is world +Z), all or none.
  void SetEnvironmentImage(int face, const char* file);
  vtkPFSetClampMacro(EnvironmentScale, double, 0.0, 1000.0);
  /// Capillary ripples: metres per tile of the normal map, strength (0 off), drift speed, and the
  /// distance beyond which they fade out.
  vtkPFSetFiniteMacro(RippleScale, double);
  vtkPFSetFiniteMacro(RippleStrength, double);
  vtkPFSetFiniteMacro(RippleSpeed, double);
  vtkPFSetFiniteMacro(RippleFade, double);
  /// Exposure of the tone mapping; with AutoExposure, chosen so the average water pixel maps to
  /// mid-grey (18 % linear) instead.
  vtkPFSetClampMacro(Exposure, double, 0.0, 100.0);
  vtkSetMacro(AutoExposure, bool);
  /// The exposure used by the last render (the automatic one when AutoExposure is on).
  double GetEffectiveExposure() const { return this->EffectiveExposure; }
  //@}

  /// Waves the GPU draws after clamping, and why a setting could not be used ("" when fine).
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkPFGerstnerOceanRepresentation();
  ~vtkPFGerstnerOceanRepresentation() override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkPFGerstnerOceanRepresentation(const vtkPFGerstnerOceanRepresentation&) = delete;
  void operator=(const vtkPFGerstnerOceanRepresentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  /// Tells the view the input's bounds grown by the waves' largest displacement (so Reset Camera
  /// and the clipping range see the waves), and warns when the surface is much narrower than the
  /// shortest wave.
  void ReportDisplacedBounds(vtkInformation* inInfo);
  std::string SizeWarningKey;

  /// Rebuilds the model (and the bathymetry textures) when parameters or the data changed.
  void UpdateModel(vtkDataObject* delivered);
  void UpdateShaders();
  void UpdateUniforms(double time);
  /// The camera's view-to-world matrix for the wave shader, as the renderer starts drawing (the
  /// camera of this render on every process).
  void UpdateViewToWorld();
  unsigned long CameraObserver = 0;

  /// Sets one field of the sea; a value that leaves the settings invalid (NaN, out of range) is
  /// ignored with a warning that names the property (SeaSettings::validate), as the source refuses it.
  template<class Field, class Value>
  void SetSea(Field& field, Value value)
  {
    const Field previous = field;
    field = static_cast<Field>(value);
    const std::string problem = this->Sea.validate();
    field = previous;
    if (!problem.empty())
    {
      vtkWarningMacro(<< problem << "; the property keeps its value");
      return;
    }
    parafluid::vtk::assignIfChanged(this, field, value);
  }
  /// The sea, shared in form with the Gerstner Ocean source (parafluid/ocean/SeaSettings.h).
  parafluid::ocean::SeaSettings Sea;
  std::string BathymetryArray;
  int ShadingMode = 0;
  double SolidColor[3] = { 1.0, 1.0, 1.0 };
  double DeepColor[3] = { 0.004, 0.016, 0.045 };
  double ShallowColor[3] = { 0.02, 0.20, 0.20 };
  double ColorDepth = 4.0;
  double FoamColor[3] = { 0.9, 0.92, 0.95 };
  double FoamAmount = 1.0;
  double SunElevation = 35.0, SunAzimuth = 200.0;
  double SunColor[3] = { 1.0, 0.95, 0.85 };
  double SunIntensity = 1.0, Shininess = 400.0;
  double HorizonColor[3] = { 0.65, 0.75, 0.85 };
  double ZenithColor[3] = { 0.12, 0.28, 0.60 };
  std::string EnvironmentImages[6];
  double EnvironmentScale = 1.0;
  double RippleScale = 4.0, RippleStrength = 0.35, RippleSpeed = 1.0, RippleFade = 300.0;
  double Exposure = 1.5;
  bool AutoExposure = false;
  double EffectiveExposure = 1.5;
  std::string LastError;
};
