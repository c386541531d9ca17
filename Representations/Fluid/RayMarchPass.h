#pragma once
// The ray-marched fluid's passes: the march (RayMarchFS.glsl) over the fluid's rectangle, straight
// into the view at full resolution, or into a reduced-resolution colour and depth pair that the
// upsampling pass (RayMarchUpsampleFS.glsl) then draws into the view with depth-aware weights.
// Programs are built per variant (opaque or transparent, with or without particle colours, full
// or reduced resolution) because llvmpipe pays for branches a uniform skips.
#include "FluidScreenQuad.h" // the passes' shared declarations

#include "vtkSmartPointer.h"

#include <map>

class vtkTexture;
class vtkTextureObject;
namespace parafluid
{
class RayMarchBuffers;

/// vtkPFRayMarchedFluidMapper's settings (its FillMarch fills every field).
struct RayMarchSettings
{
  int DisplayMode;        // vtkPFRayMarchedFluidMapper::DisplayModes
  double StepLength;      // [world units]
  int MaxSteps;           // samples of phi per ray segment
  bool Skipping;          // empty-space skipping
  double ResolutionScale; // 1, 1/2 or 1/4
  double FluidColor[3];
  double AttenuationDistance;
  double RefractiveIndex;
  double Shininess;
  double SpecularStrength;
  double Ambient;
  double ColorMix;
};

class RayMarchPass
{
public:
  RayMarchPass();
  ~RayMarchPass(); // where vtkOpenGLQuadHelper is complete
  /// Draws the fluid into the window's framebuffer (bound by the caller) over the frame's
  /// rectangle with depth test and writes. `opaqueDepth`/`opaqueColor`: the scene drawn so far
  /// (full resolution; colour only read by transparent fluid). False when a program did not build.
  /// `bounds`: RayMarchBoundsPass's start/stop depths for this march (null: rays start at the
  /// grid's box).
  bool Run(FluidFrame& frame, const RayMarchBuffers& buffers, vtkTextureObject* opaqueDepth,
           vtkTextureObject* opaqueColor, vtkTextureObject* bounds, vtkTexture* environment,
           const RayMarchSettings& settings);
  /// The resolution scale used for `resolutionScale` (1, 0.5 or 0.25), and the march's pixels
  /// along `axis` at it.
  static double ChooseScale(double resolutionScale);
  static int MarchSize(const FluidFrame& frame, double resolutionScale, int axis);
  void Release(vtkWindow* window);

private:
  void EnsureLowResolution(FluidFrame& frame, int width, int height);
  std::map<int, std::unique_ptr<vtkOpenGLQuadHelper>> March; // by variant bits
  std::unique_ptr<vtkOpenGLQuadHelper> Upsample;
  vtkSmartPointer<vtkTextureObject> LowColor, LowDepth;
};
} // namespace parafluid
