#pragma once
// Thickness (transparent fluid and the thickness display): the splatted chord lengths blurred by
// a separable Gaussian at the thickness target's reduced resolution, in two passes.
#include "FluidScreenQuad.h" // the passes' shared declarations

namespace parafluid
{

class FluidThicknessBlurPass
{
public:
  FluidThicknessBlurPass();
  ~FluidThicknessBlurPass(); // where vtkOpenGLQuadHelper is complete
  /// Blurs targets.Thickness[0] in place (through Thickness[1]) over `maxFilterRadius` full-resolution
  /// pixels; restores the full viewport and the fluid's scissor rectangle.
  void Run(FluidFrame& frame, FluidScreenTargets& targets, int maxFilterRadius);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Blur;
};
} // namespace parafluid
