#pragma once
// The Rain Splashes representation's one pass: every recent impact a sprite of the project's own
// splash sequences (parafluid::rain::splashAtlas), blended over the scene with the depth test on.
#include "vtkSmartPointer.h"

class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
class RainPointBuffer;
struct RainFrame;

class RainSplashPass
{
public:
  struct Settings
  {
    double SplashSize = 0.05; // [m]
    double Lifetime = 0.1;    // [s]
    double Brightness = 1.0;
    double Opacity = 0.8;
    float Ambient[3] = { 1.0f, 1.0f, 1.0f };
  };
  bool Run(const RainFrame& frame, const RainPointBuffer& splashes, const Settings& settings);
  void Release(vtkWindow* window);

private:
  vtkShaderProgram* Program = nullptr;
  vtkSmartPointer<vtkTextureObject> Atlas;
  unsigned int EmptyVAO = 0;
};
} // namespace parafluid
