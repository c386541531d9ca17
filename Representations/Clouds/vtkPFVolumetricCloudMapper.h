/**
 * @class vtkPFVolumetricCloudMapper
 * @brief Draws a 3-D image's scalar as a cloud: light absorbed and scattered by the density
 * (CloudMarchFS.glsl), self-shadowed through precomputed light paths, composited with the opaque
 * scene by depth.
 *
 * Used through a vtkVolume (the renderer draws it after the opaque and translucent geometry).
 * An image with no density (or none above the smallest that could show) is not marched at all.
 */
#pragma once

#include "ParaFluidCloudsRepresentationsModule.h"
#include "SetParameterMacros.h"
#include "vtkVolumeMapper.h"

#include <memory>
#include <string>

class PARAFLUIDCLOUDSREPRESENTATIONS_EXPORT vtkPFVolumetricCloudMapper : public vtkVolumeMapper
{
public:
  static vtkPFVolumetricCloudMapper* New();
  vtkTypeMacro(vtkPFVolumetricCloudMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  /// The image's bounds grown by half a sample: each sample owns the voxel around it.
  double* GetBounds() override;
  using vtkVolumeMapper::GetBounds;

  /// The array drawn as density (empty: the active point scalars).
  vtkSetStdStringFromCharMacro(DensityArray);
  vtkGetCharFromStdStringMacro(DensityArray);
  /// Extinction per unit density [1/m]: a path of density x length D has transmittance exp(-Extinction D).
  vtkPFSetClampMacro(Extinction, double, 0.0, 1e6);
  vtkGetMacro(Extinction, double);
  /// Scattering over extinction (clouds ~1, smoke less).
  vtkPFSetClampMacro(Albedo, double, 0.0, 1.0);
  vtkGetMacro(Albedo, double);
  /// Forward lobe of the Henyey-Greenstein phase function (the back lobe is -Anisotropy / 2).
  vtkPFSetClampMacro(Anisotropy, double, -0.95, 0.95);
  vtkGetMacro(Anisotropy, double);
  /// March step in samples of the image, and the most steps a ray takes.
  vtkPFSetClampMacro(StepSize, double, 0.01, 100.0);
  vtkGetMacro(StepSize, double);
  vtkPFSetClampMacro(MaxSteps, int, 1, 100000);
  vtkGetMacro(MaxSteps, int);
  /// A ray stops once less than this fraction of light gets through.
  vtkPFSetClampMacro(MinTransmittance, double, 0.0, 1.0);
  vtkGetMacro(MinTransmittance, double);
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);
  /// Scattering octaves (1: single scattering; 2-4 approximate multiple scattering).
  vtkPFSetClampMacro(Octaves, int, 1, 8);
  vtkGetMacro(Octaves, int);
  vtkPFSetClampMacro(Powder, double, 0.0, 1.0);
  vtkGetMacro(Powder, double);
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  /// 0: the view's key light (its first light that is on); 1: the sun at SunElevation, SunAzimuth.
  vtkPFSetClampMacro(LightMode, int, 0, 1);
  vtkGetMacro(LightMode, int);
  /// [degrees] above the horizon (the x-y plane) and counter-clockwise from +x.
  vtkPFSetFiniteMacro(SunElevation, double);
  vtkGetMacro(SunElevation, double);
  vtkPFSetFiniteMacro(SunAzimuth, double);
  vtkGetMacro(SunAzimuth, double);
  /// The sun's colour times its intensity (with the key light: the light's colour and intensity
  /// times LightIntensity).
  vtkPFSetClampVector3Macro(SunColor, double, 0.0, 1.0);
  vtkGetVector3Macro(SunColor, double);
  vtkPFSetClampMacro(LightIntensity, double, 0.0, 1000.0);
  vtkGetMacro(LightIntensity, double);
  /// Ambient light from the sky above (+z).
  vtkPFSetClampVector3Macro(SkyColor, double, 0.0, 10.0);
  vtkGetVector3Macro(SkyColor, double);
  /// 0: lit cloud; 1: samples taken per pixel (red = samples / 255), to see the skipping's effect.
  vtkPFSetClampMacro(DisplayMode, int, 0, 1);
  vtkGetMacro(DisplayMode, int);

  /// Whether the last Render marched at all (false: nothing to draw, no pass run).
  bool GetLastMarched() const { return this->LastMarched; }
  /// Milliseconds the last Render spent on light paths (0 when they were kept).
  double GetLastLightMilliseconds() const;

protected:
  vtkPFVolumetricCloudMapper();
  ~vtkPFVolumetricCloudMapper() override;

private:
  vtkPFVolumetricCloudMapper(const vtkPFVolumetricCloudMapper&) = delete;
  void operator=(const vtkPFVolumetricCloudMapper&) = delete;
  /// Toward the light (unit) and its colour.
  void ChooseLight(vtkRenderer* renderer, double direction[3], double color[3]) const;

  struct Internals;
  std::unique_ptr<Internals> GPU;
  std::string DensityArray = "density";
  double Extinction = 8.0;
  double Albedo = 0.95;
  double Anisotropy = 0.6;
  double StepSize = 0.5;
  int MaxSteps = 1024;
  double MinTransmittance = 0.01;
  bool Shadows = true;
  int Octaves = 3;
  double Powder = 0.0;
  bool EmptySpaceSkipping = true;
  int LightMode = 0;
  double SunElevation = 50.0;
  double SunAzimuth = 30.0;
  double SunColor[3] = { 1.0, 0.97, 0.92 };
  double LightIntensity = 12.0;
  double SkyColor[3] = { 0.25, 0.33, 0.45 };
  int DisplayMode = 0;
  bool LastMarched = false;
  std::string LastError;
};
