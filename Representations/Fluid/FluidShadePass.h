#pragma once
// The last pass of the screen-space fluid, into the view: normals from the smoothed depth,
// Schlick's Fresnel reflection of the environment (a cube map, else the view's background
// colours), refraction of the opaque scene behind with Beer-Lambert attenuation, specular from
// the renderer's lights, or toon bands and lines; and the surface's depth, so that the fluid and
// the opaque scene hide each other.
#include <memory>

class vtkOpenGLQuadHelper;
class vtkTexture;
class vtkWindow;

namespace parafluid
{
class FluidScreenTargets;
struct FluidFrame;

class FluidShadePass
{
public:
  FluidShadePass();
  ~FluidShadePass(); // where vtkOpenGLQuadHelper is complete
  struct Settings
  {
    int DisplayMode = 1; // vtkPFScreenSpaceFluidMapper::DisplayModes
    double FluidColor[3] = { 0.1, 0.45, 0.75 };
    double AttenuationDistance = 1.0;
    double RefractiveIndex = 1.33;
    double RefractionStrength = 0.1;
    double Shininess = 150.0;
    double SpecularStrength = 0.8;
    double Ambient = 0.2;
    double ColorMix = 0.8;
    int ToonBands = 4;
    double LineColor[3] = { 0.02, 0.06, 0.15 };
    double DepthContourSpacing = 0.0; // particle radii
  };
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
           const Settings& settings);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Background, CubeMap; // without and with an environment
};
} // namespace parafluid
