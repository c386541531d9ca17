#include "FluidSplatPass.h"

#include "FluidFrame.h"
#include "FluidParticleBuffers.h"
#include "FluidScreenTargets.h"
#include "FluidSplatFS.h"
#include "FluidSplatVS.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <iterator>
#include <string>

namespace parafluid
{
vtkShaderProgram* FluidSplatPass::Ready(const FluidFrame& frame, const FluidParticleBuffers& particles,
                                        const FluidScreenTargets& targets, int which)
{
  vtkShaderProgram*& program = this->Programs[which + (frame.PointSprites ? 2 : 0)];
  if (!program)
  {
    std::string vs = FluidSplatVS, fs = FluidSplatFS;
    std::string defines = "//VTK::System::Dec\n";
    defines += which == 1 ? "#define THICKNESS_PASS\n" : "";
    defines += frame.PointSprites ? "#define POINT_SPRITES\n" : "";
    vtkShaderProgram::Substitute(vs, "//VTK::System::Dec\n", defines);
    vtkShaderProgram::Substitute(fs, "//VTK::System::Dec\n", defines);
    program = frame.Window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
  }
  else
  {
    frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  }
  if (!program)
  {
    return nullptr;
  }
  const float fullSize[2] = { static_cast<float>(frame.Size[0]), static_cast<float>(frame.Size[1]) };
  program->SetUniformi("particles", particles.Particles()->GetTextureUnit());
  program->SetUniformi("hasColors", particles.HasColors() ? 1 : 0);
  // Unused without colours, but a sampler left on unit 0 could alias a different sampler type.
  program->SetUniformi("particleColors",
                       (particles.HasColors() ? particles.Colors() : particles.Particles())->GetTextureUnit());
  program->SetUniformi("opaqueDepth", targets.OpaqueDepth->GetTextureUnit());
  program->SetUniformi("useOpaqueDepth", 1);
  program->SetUniformf("opaqueDepthScale", 1.0f);
  program->SetUniformMatrix("MCVCMatrix", frame.ModelView);
  program->SetUniformMatrix("VCDCMatrix", frame.Projection);
  program->SetUniformi("parallelProjection", frame.Parallel ? 1 : 0);
  program->SetUniformf("nearDistance", static_cast<float>(frame.NearDistance));
  program->SetUniform4f("projection", frame.ProjectionCoefficients);
  program->SetUniform2f("targetSize", fullSize);
  return program;
}

bool FluidSplatPass::Prepare(const FluidFrame& frame, const FluidParticleBuffers& particles,
                             const FluidScreenTargets& targets, bool thickness)
{
  // The samplers' units are assigned on activation; Run activates them before readying again.
  particles.Particles()->Activate();
  if (particles.HasColors())
  {
    particles.Colors()->Activate();
  }
  targets.OpaqueDepth->Activate();
  // (The depth program is readied last, so it is the one bound for the first draw.)
  const bool ready =
    (!thickness || this->Ready(frame, particles, targets, 1)) && this->Ready(frame, particles, targets, 0);
  if (!ready)
  {
    particles.Particles()->Deactivate();
    if (particles.HasColors())
    {
      particles.Colors()->Deactivate();
    }
    targets.OpaqueDepth->Deactivate();
  }
  return ready;
}

void FluidSplatPass::Draw(const FluidFrame& frame, vtkIdType count) const
{
  if (frame.PointSprites)
  {
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
  }
  else
  {
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * count));
  }
}

void FluidSplatPass::Run(FluidFrame& frame, const FluidParticleBuffers& particles, FluidScreenTargets& targets,
                         bool thickness)
{
  vtkOpenGLState* state = frame.State;
  vtkOpenGLFramebufferObject* fbo = targets.Framebuffer;
  const bool colors = particles.HasColors();
  this->ThicknessFactor = 0;
  glBindVertexArray(targets.EmptyVAO);
  // GL_PROGRAM_POINT_SIZE is not tracked by vtkOpenGLState: set raw and restored.
  const GLboolean programPointSize = glIsEnabled(GL_PROGRAM_POINT_SIZE);
  if (frame.PointSprites)
  {
    glEnable(GL_PROGRAM_POINT_SIZE);
  }

  fbo->AddColorAttachment(0, targets.Depth[0]);
  if (colors)
  {
    fbo->AddColorAttachment(1, targets.ParticleColors);
  }
  fbo->AddDepthAttachment(targets.SplatDepth);
  fbo->ActivateDrawBuffers(colors ? 2 : 1);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDisable(GL_BLEND);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  this->Draw(frame, particles.Count());
  ++frame.PassCount;
  if (colors)
  {
    fbo->RemoveColorAttachment(1);
  }
  fbo->RemoveDepthAttachment();
  fbo->ActivateDrawBuffers(1);

  if (thickness)
  {
    const int f = targets.ThicknessFactor;
    vtkShaderProgram* program = this->Ready(frame, particles, targets, 1);
    fbo->AddColorAttachment(0, targets.Thickness[0]);
    const int size[2] = { (frame.Size[0] + f - 1) / f, (frame.Size[1] + f - 1) / f };
    const int lo[2] = { frame.RectMin[0] / f, frame.RectMin[1] / f };
    const int hi[2] = { (frame.RectMax[0] + f - 1) / f, (frame.RectMax[1] + f - 1) / f };
    state->vtkglViewport(0, 0, size[0], size[1]);
    state->vtkglScissor(lo[0], lo[1], hi[0] - lo[0], hi[1] - lo[1]);
    program->SetUniformf("opaqueDepthScale", static_cast<float>(f));
    this->ThicknessFactor = f;
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    const float pixels[2] = { static_cast<float>(size[0]), static_cast<float>(size[1]) };
    program->SetUniform2f("targetSize", pixels);
    this->Draw(frame, particles.Count());
    state->vtkglDisable(GL_BLEND);
    ++frame.PassCount;
  }
  glBindVertexArray(0);
  if (!programPointSize)
  {
    glDisable(GL_PROGRAM_POINT_SIZE);
  }
  particles.Particles()->Deactivate();
  if (colors)
  {
    particles.Colors()->Deactivate();
  }
  targets.OpaqueDepth->Deactivate();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
}

void FluidSplatPass::Release(vtkWindow*)
{
  // The programs belong to the window's shader cache, which releases them.
  std::fill(std::begin(this->Programs), std::end(this->Programs), nullptr);
  this->ThicknessFactor = 0;
}
} // namespace parafluid
