#pragma once
// The Rain representation's streaks drawn on the CPU (parafluid::rain::StreakRaster) and laid over
// the scene as one textured quad: the path for a software OpenGL such as Mesa's llvmpipe, where a
// triangle per drop costs about half a microsecond of setup (Testing/Benchmarks/README.md, "Rain").
// The scene's depth is read back first, so the scene still hides the streaks behind it; the image
// is what RainStreakPass draws, blended in the drops' order, within the rounding of an 8-bit
// framebuffer.
#include "parafluid/rain/StreakRaster.h"

#include "vtkSmartPointer.h"

#include <memory>
#include <vector>

class vtkOpenGLQuadHelper;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
struct RainFrame;

class RainStreakCpuPass
{
public:
  RainStreakCpuPass();
  ~RainStreakCpuPass();
  /// Draws the drops (8 floats each, RainPointBuffer's packing) lit by `radiance` (RGBA, columns
  /// by rows); false when the scene's depth could not be read (a multisampled framebuffer) or the
  /// compositing shader did not compile: the caller then draws them on the GPU.
  bool Run(const RainFrame& frame, const std::vector<float>& drops, const rain::RadianceTable& radiance,
           const rain::StreakLook& look);
  void Release(vtkWindow* window);

  /// Whether the current context's OpenGL rasterises on the CPU (llvmpipe, softpipe, SWR).
  static bool SoftwareRenderer();

private:
  rain::StreakRaster Raster;
  std::vector<float> Depth; // the scene's window depth, row 0 at the bottom
  std::vector<float> Image; // what the streaks add: premultiplied colour and coverage
  vtkSmartPointer<vtkTextureObject> Texture;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};
} // namespace parafluid
