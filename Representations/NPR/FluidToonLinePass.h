#pragma once
// Toon display: line coverage from the smoothed depth by a flow-guided difference of Gaussians
// (Kang, Lee & Chui 2007) in five passes: the structure tensor of the depth, its separable blur,
// the DoG across the edges, and its average along them, thresholded.
#include "FluidScreenQuad.h" // the passes' shared declarations

namespace parafluid
{

class FluidToonLinePass
{
public:
  FluidToonLinePass();
  ~FluidToonLinePass(); // where vtkOpenGLQuadHelper is complete
  struct Settings
  {
    double DepthRange = 2.0;    // particle radii per unit of the line image
    double LineWidth = 1.0;     // DoG sigma [pixels]
    double LineThreshold = 0.1; // response at which a line is drawn
  };
  /// Lines of targets.Depth[depth] into targets.Lines (the other depth target is scratch).
  void Run(FluidFrame& frame, FluidScreenTargets& targets, int depth, const Settings& settings);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Tensor, Blur, DoG, Flow;
};
} // namespace parafluid
