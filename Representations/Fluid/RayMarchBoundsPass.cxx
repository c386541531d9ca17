#include "RayMarchBoundsPass.h"

#include "FluidScreenTargets.h"
#include "RayMarchBoundsFS.h"
#include "RayMarchBoundsVS.h"
#include "RayMarchBuffers.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace parafluid
{
bool RayMarchBoundsPass::Run(FluidFrame& frame, const RayMarchBuffers& buffers, unsigned int emptyVAO,
                             const int marchSize[2], double pixelScale, bool separateSplash)
{
  const int size[2] = { (marchSize[0] + BoundsPixels - 1) / BoundsPixels,
                        (marchSize[1] + BoundsPixels - 1) / BoundsPixels };
  if (!this->Target)
  {
    this->Target = makeScreenTexture(frame.Window);
    this->Target->SetInternalFormat(GL_RGBA32F);
    this->Target->SetFormat(GL_RGBA);
    this->Target->Allocate2D(size[0], size[1], 4, VTK_FLOAT);
  }
  else if (static_cast<int>(this->Target->GetWidth()) != size[0] ||
           static_cast<int>(this->Target->GetHeight()) != size[1])
  {
    this->Target->Resize(size[0], size[1]);
  }
  vtkOpenGLShaderCache* cache = frame.Window->GetShaderCache();
  vtkShaderProgram* program = this->Program ? (cache->ReadyShaderProgram(this->Program), this->Program)
                                            : cache->ReadyShaderProgram(RayMarchBoundsVS, RayMarchBoundsFS, "");
  this->Program = program;
  if (!program || !program->GetCompiled())
  {
    return false;
  }
  const surface::DensityCellGrid& grid = buffers.Grid();
  buffers.SplatCells()->Activate();
  program->SetUniformi("splatCells", buffers.SplatCells()->GetTextureUnit());
  program->SetUniformMatrix("MCVCMatrix", frame.ModelView);
  program->SetUniformMatrix("VCDCMatrix", frame.Projection);
  program->SetUniformf("cellSize", static_cast<float>(grid.cellSize()));
  program->SetUniformf("kernelRadius", static_cast<float>(grid.kernelRadius()));
  program->SetUniformf("nearDistance", static_cast<float>(frame.NearDistance));
  const float viewport[2] = { static_cast<float>(frame.Size[0]), static_cast<float>(frame.Size[1]) };
  const float target[2] = { static_cast<float>(size[0]), static_cast<float>(size[1]) };
  program->SetUniform2f("viewportSize", viewport);
  program->SetUniform2f("boundsSize", target);
  program->SetUniformf("boundsPixel", static_cast<float>(pixelScale * BoundsPixels));
  program->SetUniformi("separateSplash", separateSplash ? 1 : 0);

  vtkOpenGLState* state = frame.State;
  state->PushFramebufferBindings();
  frame.Framebuffer->Bind();
  frame.Framebuffer->AddColorAttachment(0, this->Target);
  frame.Framebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, size[0], size[1]);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClearColor(1e30, 1e30, 1e30, 1e30);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendEquation(GL_MIN);
  glBindVertexArray(emptyVAO);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * (grid.splatCells().size() / 4)));
  glBindVertexArray(0);
  ++frame.PassCount;
  state->vtkglBlendEquation(GL_FUNC_ADD);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_SCISSOR_TEST);
  frame.Framebuffer->RemoveColorAttachment(0);
  state->PopFramebufferBindings();
  buffers.SplatCells()->Deactivate();
  return true;
}

void RayMarchBoundsPass::Release(vtkWindow* window)
{
  // The program belongs to the window's shader cache, which releases it.
  this->Program = nullptr;
  if (this->Target)
  {
    this->Target->ReleaseGraphicsResources(window);
  }
  this->Target = nullptr;
}
} // namespace parafluid
