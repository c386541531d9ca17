#include "FluidThicknessBlurPass.h"

#include "FluidGaussianBlurFS.h"
#include "FluidScreenQuad.h"
#include "FluidScreenTargets.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

#include <algorithm>

namespace parafluid
{
FluidThicknessBlurPass::FluidThicknessBlurPass() = default;
FluidThicknessBlurPass::~FluidThicknessBlurPass() = default;

void FluidThicknessBlurPass::Run(FluidFrame& frame, FluidScreenTargets& targets, int maxFilterRadius)
{
  const int f = targets.ThicknessFactor;
  const int lo[2] = { frame.RectMin[0] / f, frame.RectMin[1] / f };
  const int hi[2] = { (frame.RectMax[0] + f - 1) / f, (frame.RectMax[1] + f - 1) / f };
  const float pixels[2] = { static_cast<float>((frame.Size[0] + f - 1) / f),
                            static_cast<float>((frame.Size[1] + f - 1) / f) };
  vtkShaderProgram* program = readyScreenQuad(this->Blur, frame, FluidGaussianBlurFS);
  // The thickness target's own rectangle and size.
  program->SetUniform2i("rectMin", lo);
  program->SetUniform2i("rectMax", hi);
  program->SetUniform2f("viewportSize", pixels);
  program->SetUniformi("radius", std::max(1, (maxFilterRadius + f) / (2 * f)));
  const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
  program->SetUniform2i("stepDir", dx);
  runScreenQuad(frame, this->Blur.get(), targets.Thickness[0], targets.Thickness[1], "sourceTex");
  program->SetUniform2i("stepDir", dy);
  runScreenQuad(frame, this->Blur.get(), targets.Thickness[1], targets.Thickness[0], "sourceTex");
  frame.State->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  frame.State->vtkglScissor(frame.RectMin[0], frame.RectMin[1], frame.RectWidth(), frame.RectHeight());
}

void FluidThicknessBlurPass::Release(vtkWindow* window)
{
  releaseScreenQuad(this->Blur, window);
}
} // namespace parafluid
