#pragma once
// The narrow-range filter at reduced resolution, for particles so large on screen that its width
// (FilterSize particle radii) needs more taps than MaxFilterRadius: the splatted depth goes down to
// a target `factor` (2 to 16) times smaller each way, is filtered there with dense taps, and comes
// back depth-aware with cubic B-spline weights (FluidDepthResampleFS.glsl). Spreading the taps
// instead (a trous) streaks close-ups, where the taps fall into the holes between spheres tens of
// pixels wide; here every pixel of the small target sees its whole neighbourhood.
#include "FluidScreenQuad.h" // the passes' shared declarations

#include "vtkSmartPointer.h"

namespace parafluid
{
class FluidReducedSmoothing
{
public:
  FluidReducedSmoothing();
  ~FluidReducedSmoothing(); // where vtkOpenGLQuadHelper is complete
  /// The reduction for a filter `reach` pixels wide each side at the fluid's nearest depth, with
  /// at most `maxTaps` taps each side: 1 up to twice maxTaps (a trous taps at most every other
  /// pixel are still clean), else a power of two up to 16.
  static int ChooseFactor(double reach, int maxTaps);
  /// Filters targets.Depth[0] with `narrowRange` (its program readied with the frame's
  /// uniforms: `iterations` pairs of 1D passes, the last `filterSize` particle radii wide, each
  /// earlier one half as wide) on the small target and writes the result into targets.Depth[1].
  /// `band`: depth [world units] that counts as one surface. Leaves the viewport and scissor on
  /// the frame's rectangle.
  void Run(FluidFrame& frame, FluidScreenTargets& targets, vtkOpenGLQuadHelper* narrowRange, int iterations,
           double filterSize, int factor, double band);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Down, Up;
  vtkSmartPointer<vtkTextureObject> Small[2];
};
} // namespace parafluid
