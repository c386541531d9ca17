#include "FluidToonLinePass.h"

#include "FluidGaussianBlurFS.h"
#include "FluidScreenQuad.h"
#include "FluidScreenTargets.h"
#include "FluidToonDoGFS.h"
#include "FluidToonFlowFS.h"
#include "FluidToonTensorFS.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace parafluid
{
FluidToonLinePass::FluidToonLinePass() = default;
FluidToonLinePass::~FluidToonLinePass() = default;

void FluidToonLinePass::Run(FluidFrame& frame, FluidScreenTargets& targets, int depth, const Settings& settings)
{
  // The line image: depth in units of DepthRange particle radii; the background three units
  // behind the farthest fluid, so a silhouette is always a strong edge, stronger than any
  // depth step inside the fluid that still counts as one surface.
  const float lineScale = static_cast<float>(1.0 / (frame.MaxRadius * settings.DepthRange));
  const float background = static_cast<float>(frame.Farthest) * lineScale + 3.0f;
  vtkShaderProgram* program = readyScreenQuad(this->Tensor, frame, FluidToonTensorFS);
  program->SetUniformf("lineDepthScale", lineScale);
  program->SetUniformf("backgroundValue", background);
  runScreenQuad(frame, this->Tensor.get(), targets.Depth[depth], targets.Tensor[0], "depthTex");

  program = readyScreenQuad(this->Blur, frame, FluidGaussianBlurFS);
  program->SetUniformi("radius", 4);
  const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
  program->SetUniform2i("stepDir", dx);
  runScreenQuad(frame, this->Blur.get(), targets.Tensor[0], targets.Tensor[1], "sourceTex");
  program->SetUniform2i("stepDir", dy);
  runScreenQuad(frame, this->Blur.get(), targets.Tensor[1], targets.Tensor[0], "sourceTex");

  // The DoG goes into the free depth target.
  vtkTextureObject* dog = targets.Depth[1 - depth];
  program = readyScreenQuad(this->DoG, frame, FluidToonDoGFS);
  program->SetUniformf("lineDepthScale", lineScale);
  program->SetUniformf("backgroundValue", background);
  program->SetUniformf("sigma", static_cast<float>(std::max(0.5, settings.LineWidth)));
  targets.Tensor[0]->Activate();
  program->SetUniformi("tensorTex", targets.Tensor[0]->GetTextureUnit());
  runScreenQuad(frame, this->DoG.get(), targets.Depth[depth], dog, "depthTex");

  program = readyScreenQuad(this->Flow, frame, FluidToonFlowFS);
  program->SetUniformi("tensorTex", targets.Tensor[0]->GetTextureUnit());
  program->SetUniformf("flowSigma", 3.0f);
  program->SetUniformf("threshold", static_cast<float>(settings.LineThreshold));
  runScreenQuad(frame, this->Flow.get(), dog, targets.Lines, "dogTex");
  targets.Tensor[0]->Deactivate();
}

void FluidToonLinePass::Release(vtkWindow* window)
{
  for (auto* quad : { &this->Tensor, &this->Blur, &this->DoG, &this->Flow })
  {
    releaseScreenQuad(*quad, window);
  }
}
} // namespace parafluid
