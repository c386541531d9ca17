#pragma once
// The last pass of the screen-space fluid, into the view: normals from the smoothed depth,
// Schlick's Fresnel reflection of the environment (a cube map, else the view's background
// colours), refraction of the opaque scene behind with Beer-Lambert attenuation, specular from
// the renderer's lights, or toon bands and lines; and the surface's depth, so that the fluid and
// the opaque scene hide each other.
#include "FluidScreenQuad.h" // the passes' shared declarations

class vtkTexture;
namespace parafluid
{

/// The mapper's settings of the same names (vtkPFScreenSpaceFluidMapper::FillShading fills every field).
struct FluidShadeSettings
{
  int DisplayMode; // vtkPFScreenSpaceFluidMapper::DisplayModes
  double FluidColor[3];
  double AttenuationDistance;
  double RefractiveIndex;
  double RefractionStrength;
  double Shininess;
  double SpecularStrength;
  double Ambient;
  double ColorMix;
  int ToonBands;
  double LineColor[3];
  double DepthContourSpacing; // particle radii
  bool SmoothSilhouettes;
};

class FluidShadePass
{
public:
  FluidShadePass();
  ~FluidShadePass(); // where vtkOpenGLQuadHelper is complete
  /// What the pass reads: the smoothed depth target, and which of the other targets hold data.
  struct Inputs
  {
    int Depth = 0;
    bool Thickness = false;
    bool OpaqueColor = false;
    bool ParticleColors = false;
    bool Lines = false;
  };
  /// Draws into the window's framebuffer (bound by the caller) over the frame's rectangle, with
  /// the depth test on and depth writes on. `environment`: the mapper's cube map or null (then the
  /// renderer's environment cube map, else the background colours).
  void Run(FluidFrame& frame, FluidScreenTargets& targets, const Inputs& inputs, vtkTexture* environment,
           const FluidShadeSettings& settings);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Background, CubeMap; // without and with an environment
};
} // namespace parafluid
