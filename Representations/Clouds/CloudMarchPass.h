#pragma once
// The Volumetric Cloud's one full-screen pass (CloudMarchFS.glsl): a ray per pixel of the
// renderer's viewport through the cloud textures, stopped at the opaque scene's depth, blended
// over the view premultiplied.
#include <memory>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
class CloudVolumeTextures;

struct CloudMarchSettings
{
  double Extinction = 8.0;      // [1/m per unit density]
  double LightExtinction = 8.0; // the light paths' [1/m per unit density] (CloudMarchFS.glsl says why)
  double Albedo = 0.95;
  double Anisotropy = 0.6;
  double StepLength = 0.01; // [m]
  int MaxSteps = 512;
  double MinTransmittance = 0.01;
  double EmptyDensity = 0.0; // blocks below it are skipped; negative: never skip
  double LightDirection[3] = { 0.0, 0.0, 1.0 };
  double LightColor[3] = { 1.0, 1.0, 1.0 };
  double SkyColor[3] = { 0.3, 0.4, 0.55 };
  bool Shadows = true;
  int Octaves = 3;
  double Powder = 0.0;
  int DisplayMode = 0;     // 0 lit, 1 samples per pixel
  bool WriteDepth = false; // under MPI (depth compositing across processes)
};

class CloudMarchPass
{
public:
  CloudMarchPass();
  ~CloudMarchPass();
  /// Copies the opaque depth of the viewport and marches; false when the shader did not compile.
  bool Run(vtkOpenGLRenderWindow* window, vtkRenderer* renderer, const CloudVolumeTextures& textures,
           const CloudMarchSettings& settings);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkTextureObject* OpaqueDepth = nullptr;
};
} // namespace parafluid
