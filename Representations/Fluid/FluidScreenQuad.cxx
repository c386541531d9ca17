#include "FluidScreenQuad.h"

#include "FluidScreenCommon.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <string>

namespace parafluid
{
vtkShaderProgram* readyScreenQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad, const FluidFrame& frame, const char* body,
                                  const char* defines)
{
  if (!quad)
  {
    const std::string fs = std::string("//VTK::System::Dec\n") + defines + FluidScreenCommon + body;
    quad.reset(new vtkOpenGLQuadHelper(frame.Window, nullptr, fs.c_str(), ""));
  }
  else
  {
    frame.Window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  vtkShaderProgram* program = quad->Program;
  if (!program)
  {
    return nullptr; // did not compile (the shader cache reported why)
  }
  const float viewport[2] = { static_cast<float>(frame.Size[0]), static_cast<float>(frame.Size[1]) };
  program->SetUniform2i("rectMin", frame.RectMin);
  program->SetUniform2i("rectMax", frame.RectMax);
  program->SetUniform2f("viewportSize", viewport);
  program->SetUniformi("parallelProjection", frame.Parallel ? 1 : 0);
  program->SetUniform4f("projection", frame.ProjectionCoefficients);
  return program;
}

void runScreenQuad(FluidFrame& frame, vtkOpenGLQuadHelper* quad, vtkTextureObject* source, vtkTextureObject* target,
                   const char* sourceName)
{
  frame.Framebuffer->AddColorAttachment(0, target);
  source->Activate();
  quad->Program->SetUniformi(sourceName, source->GetTextureUnit());
  quad->Render();
  source->Deactivate();
  ++frame.PassCount;
}

void releaseScreenQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkWindow* window)
{
  if (quad)
  {
    quad->ReleaseGraphicsResources(window);
    quad.reset();
  }
}
} // namespace parafluid
