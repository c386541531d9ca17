#include "FluidDepthSmoothingPass.h"

#include "FluidBilateralFS.h"
#include "FluidCurvatureFlowFS.h"
#include "FluidNarrowRangeFS.h"
#include "FluidScreenQuad.h"
#include "FluidScreenTargets.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkShaderProgram.h"

#include <algorithm>

namespace parafluid
{
FluidDepthSmoothingPass::FluidDepthSmoothingPass() = default;
FluidDepthSmoothingPass::~FluidDepthSmoothingPass() = default;

int FluidDepthSmoothingPass::Run(FluidFrame& frame, FluidScreenTargets& targets, const Settings& settings)
{
  static const char* const bodies[3] = { FluidNarrowRangeFS, FluidBilateralFS, FluidCurvatureFlowFS };
  const int method = settings.Method >= NarrowRange && settings.Method <= CurvatureFlow ? settings.Method : NarrowRange;
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Quads[method];
  vtkShaderProgram* program = readyScreenQuad(quad, frame, bodies[method]);
  // The filters work in the radius of the particles on screen: the largest one is the safe
  // choice for the band of depths that count as one surface.
  program->SetUniformf("particleRadius", static_cast<float>(frame.MaxRadius));
  program->SetUniformf("rangeFactor", static_cast<float>(settings.DepthRange));
  int current = 0;
  if (method == CurvatureFlow)
  {
    program->SetUniformf("stepFactor", static_cast<float>(settings.CurvatureFlowStep));
    for (int i = 0; i < settings.Iterations; ++i)
    {
      runScreenQuad(frame, quad.get(), targets.Depth[current], targets.Depth[1 - current], "depthTex");
      current = 1 - current;
    }
    return current;
  }
  program->SetUniformf("filterSize", static_cast<float>(settings.FilterSize));
  program->SetUniformi("maxRadius", settings.MaxFilterRadius);
  program->SetUniformi("spreadTaps", settings.SpreadTaps ? 1 : 0);
  this->Factor = 1;
  if (method == NarrowRange && settings.SpreadTaps)
  {
    // The filter's reach (2 sigma = FilterSize radii) in pixels at the fluid's nearest depth.
    const double perUnit = 0.5 * frame.Size[0] * frame.ProjectionCoefficients[0];
    const double nearest = std::max(frame.Nearest, frame.NearDistance);
    const double radius = frame.MaxRadius * (frame.Parallel ? perUnit : perUnit / std::max(nearest, 1e-12));
    this->Factor = FluidReducedSmoothing::ChooseFactor(settings.FilterSize * radius, settings.MaxFilterRadius);
    if (this->Factor > 1)
    {
      this->Reduced.Run(frame, targets, quad.get(), settings.Iterations, settings.FilterSize, this->Factor,
                        settings.DepthRange * frame.MaxRadius);
      return 1;
    }
  }
  const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
  for (int i = 0; i < settings.Iterations; ++i)
  {
    // A trous: the last iteration at the full stride, each earlier one at half the next's.
    program->SetUniformi("strideShift", std::min(settings.Iterations - 1 - i, 8));
    program->SetUniform2i("stepDir", dx);
    runScreenQuad(frame, quad.get(), targets.Depth[0], targets.Depth[1], "depthTex");
    program->SetUniform2i("stepDir", dy);
    runScreenQuad(frame, quad.get(), targets.Depth[1], targets.Depth[0], "depthTex");
  }
  return current;
}

void FluidDepthSmoothingPass::Release(vtkWindow* window)
{
  this->Reduced.Release(window);
  for (auto& quad : this->Quads)
  {
    releaseScreenQuad(quad, window);
  }
}
} // namespace parafluid
