#include "FluidReducedSmoothing.h"

#include "FluidDepthResampleFS.h"
#include "FluidScreenTargets.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace parafluid
{
FluidReducedSmoothing::FluidReducedSmoothing() = default;
FluidReducedSmoothing::~FluidReducedSmoothing() = default;

int FluidReducedSmoothing::ChooseFactor(double reach, int maxTaps)
{
  if (reach <= 2.0 * maxTaps)
  {
    return 1; // taps spread to every other pixel at most: the a trous filter is still clean
  }
  int factor = 1;
  while (factor < 16 && reach / factor > maxTaps)
  {
    factor *= 2;
  }
  return factor;
}

void FluidReducedSmoothing::Run(FluidFrame& frame, FluidScreenTargets& targets, vtkOpenGLQuadHelper* narrowRange,
                                int iterations, double filterSize, int factor, double band)
{
  const int f = factor;
  const int size[2] = { (frame.Size[0] + f - 1) / f, (frame.Size[1] + f - 1) / f };
  const int lo[2] = { frame.RectMin[0] / f, frame.RectMin[1] / f };
  const int hi[2] = { (frame.RectMax[0] + f - 1) / f, (frame.RectMax[1] + f - 1) / f };
  for (auto& t : this->Small)
  {
    if (!t)
    {
      t = makeScreenTexture(frame.Window);
      t->SetInternalFormat(GL_R32F);
      t->SetFormat(GL_RED);
      t->Allocate2D(size[0], size[1], 1, VTK_FLOAT);
    }
    else if (static_cast<int>(t->GetWidth()) != size[0] || static_cast<int>(t->GetHeight()) != size[1])
    {
      t->Resize(size[0], size[1]);
    }
  }
  vtkOpenGLState* state = frame.State;
  const float smallPixels[2] = { static_cast<float>(size[0]), static_cast<float>(size[1]) };
  state->vtkglViewport(0, 0, size[0], size[1]);
  state->vtkglScissor(lo[0], lo[1], hi[0] - lo[0], hi[1] - lo[1]);

  // Down: the small target's own rectangle and size; reads the frame's.
  vtkShaderProgram* down = readyScreenQuad(this->Down, frame, FluidDepthResampleFS, "#define DOWNSAMPLE\n");
  down->SetUniform2i("rectMin", lo);
  down->SetUniform2i("rectMax", hi);
  down->SetUniform2f("viewportSize", smallPixels);
  down->SetUniform2i("otherRectMin", frame.RectMin);
  down->SetUniform2i("otherRectMax", frame.RectMax);
  down->SetUniformi("factor", f);
  down->SetUniformf("band", static_cast<float>(band));
  runScreenQuad(frame, this->Down.get(), targets.Depth[0], this->Small[0], "sourceTex");

  // The narrow-range filter on the small target, dense taps (its program was readied last by the caller).
  vtkShaderProgram* filter = narrowRange->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(filter);
  filter->SetUniform2i("rectMin", lo);
  filter->SetUniform2i("rectMax", hi);
  filter->SetUniform2f("viewportSize", smallPixels);
  filter->SetUniformi("spreadTaps", 0);
  filter->SetUniformi("strideShift", 0);
  const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
  for (int i = 0; i < iterations; ++i)
  {
    // As the a trous taps do: each iteration before the last at half the next one's width (three
    // at the full width would round the fluid's edges over three times as far).
    filter->SetUniformf("filterSize", static_cast<float>(std::ldexp(filterSize, -std::min(iterations - 1 - i, 8))));
    filter->SetUniform2i("stepDir", dx);
    runScreenQuad(frame, narrowRange, this->Small[0], this->Small[1], "depthTex");
    filter->SetUniform2i("stepDir", dy);
    runScreenQuad(frame, narrowRange, this->Small[1], this->Small[0], "depthTex");
  }

  // Up, into the frame's rectangle.
  state->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  state->vtkglScissor(frame.RectMin[0], frame.RectMin[1], frame.RectWidth(), frame.RectHeight());
  vtkShaderProgram* up = readyScreenQuad(this->Up, frame, FluidDepthResampleFS);
  up->SetUniform2i("otherRectMin", lo);
  up->SetUniform2i("otherRectMax", hi);
  up->SetUniformi("factor", f);
  up->SetUniformf("band", static_cast<float>(band));
  up->SetUniformf("particleRadius", static_cast<float>(frame.MaxRadius));
  targets.Depth[0]->Activate();
  up->SetUniformi("depthTex", targets.Depth[0]->GetTextureUnit());
  runScreenQuad(frame, this->Up.get(), this->Small[0], targets.Depth[1], "sourceTex");
  targets.Depth[0]->Deactivate();
}

void FluidReducedSmoothing::Release(vtkWindow* window)
{
  releaseScreenQuad(this->Down, window);
  releaseScreenQuad(this->Up, window);
  for (auto& t : this->Small)
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
    t = nullptr;
  }
}
} // namespace parafluid
