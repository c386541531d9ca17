#pragma once
// Pass 2 of the screen-space fluid: smoothing of the splatted depth, one strategy chosen by the
// method: the narrow-range filter (Truong & Yuksel 2018) or the bilateral filter as separable
// pairs of 1D passes per iteration, or screen-space curvature flow (van der Laan et al. 2009),
// one pass per iteration. Depth steps larger than the depth range stay edges. When the
// narrow-range filter's width needs more than MaxFilterRadius taps at the fluid's nearest depth,
// it runs at reduced resolution (FluidReducedSmoothing).
#include "FluidReducedSmoothing.h"
#include "FluidScreenQuad.h" // the passes' shared declarations

namespace parafluid
{

class FluidDepthSmoothingPass
{
public:
  FluidDepthSmoothingPass();
  ~FluidDepthSmoothingPass(); // where vtkOpenGLQuadHelper is complete
  enum Method
  {
    NarrowRange = 0,
    Bilateral = 1,
    CurvatureFlow = 2
  };
  struct Settings
  {
    int Method = NarrowRange;
    int Iterations = 3;
    double FilterSize = 2.0;  // narrow-range and bilateral: width in particle radii
    int MaxFilterRadius = 12; // ... at most this many taps each side
    bool SpreadTaps = true;   // reach kept when the width needs more taps (reduced resolution, else a trous), else cut
    double DepthRange = 2.0;  // particle radii of depth that count as one surface
    double CurvatureFlowStep = 0.8; // fraction of the explicit scheme's stability limit
  };
  /// Smooths targets.Depth[0] (ping-ponging with Depth[1]); returns the index of the target that
  /// holds the result.
  int Run(FluidFrame& frame, FluidScreenTargets& targets, const Settings& settings);
  void Release(vtkWindow* window);
  /// The reduction of the last narrow-range smoothing (1: full resolution).
  int LastFactor() const { return this->Factor; }

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quads[3]; // one program per method, built when first used
  FluidReducedSmoothing Reduced;
  int Factor = 1;
};
} // namespace parafluid
