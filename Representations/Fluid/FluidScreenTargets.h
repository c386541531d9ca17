#pragma once
// The screen-space fluid's render targets, the size of the viewport: the opaque scene's depth and
// colour, the splatted depth (ping-pong pair for smoothing), thickness at reduced resolution,
// particle colours, and for toon lines the structure tensor and line coverage; the framebuffer
// the passes draw through and an empty vertex array. Created on first use and resized with the
// viewport; targets a display mode does not need are not created.
#include "vtkOpenGLFramebufferObject.h" // vtkSmartPointer members need the full types
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include <array>

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace parafluid
{
struct FluidFrame;

/// A texture of the window with nearest filtering and clamped edges.
vtkSmartPointer<vtkTextureObject> makeScreenTexture(vtkOpenGLRenderWindow* window);

class FluidScreenTargets
{
public:
  /// (Re)creates the targets for a viewport of width x height; `thicknessFactor`: full-resolution
  /// pixels per thickness pixel, each way.
  void Ensure(vtkOpenGLRenderWindow* window, int width, int height, int thicknessFactor, bool colors, bool toon);
  /// Copies the opaque scene drawn so far (its depth, and its colour when `withColor`) inside the
  /// frame's rectangle from the framebuffer being drawn.
  void CopyOpaqueScene(const FluidFrame& frame, bool withColor);

  vtkSmartPointer<vtkTextureObject> OpaqueDepth, OpaqueColor, SplatDepth, ParticleColors;
  std::array<vtkSmartPointer<vtkTextureObject>, 2> Depth, Thickness, Tensor;
  vtkSmartPointer<vtkTextureObject> Lines;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  /// Core profiles draw only with a vertex array bound, even one without attributes.
  unsigned int EmptyVAO = 0;
  int ThicknessFactor = 0;

  void Release(vtkWindow* window);

private:
  int Width = 0, Height = 0;
};
} // namespace parafluid
