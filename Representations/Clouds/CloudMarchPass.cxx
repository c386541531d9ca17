#include "CloudMarchPass.h"

#include "CloudMarchFS.h"
#include "CloudVolumeTextures.h"

#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cmath>
#include <string>

namespace parafluid
{
CloudMarchPass::CloudMarchPass() = default;

CloudMarchPass::~CloudMarchPass()
{
  if (this->OpaqueDepth)
  {
    this->OpaqueDepth->Delete();
  }
}

bool CloudMarchPass::Run(vtkOpenGLRenderWindow* window, vtkRenderer* renderer, const CloudVolumeTextures& textures,
                         const CloudMarchSettings& s)
{
  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width < 1 || height < 1)
  {
    return true;
  }
  vtkOpenGLState* state = window->GetState();
  // The opaque scene's depth, copied from the framebuffer being drawn (the march stops there).
  if (!this->OpaqueDepth)
  {
    this->OpaqueDepth = vtkTextureObject::New();
  }
  if (this->OpaqueDepth->GetContext() != window || this->OpaqueDepth->GetWidth() != static_cast<unsigned>(width) ||
      this->OpaqueDepth->GetHeight() != static_cast<unsigned>(height))
  {
    this->OpaqueDepth->SetContext(window);
    this->OpaqueDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->OpaqueDepth->SetMinificationFilter(vtkTextureObject::Nearest);
    this->OpaqueDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  {
    GLint drawFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
    state->PushReadFramebufferBinding();
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
    this->OpaqueDepth->Bind();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, x0, y0, width, height);
    this->OpaqueDepth->Deactivate();
    state->PopReadFramebufferBinding();
  }

  if (!this->Quad)
  {
    const std::string fs = std::string("//VTK::System::Dec\n") + CloudMarchFS;
    this->Quad.reset(new vtkOpenGLQuadHelper(window, nullptr, fs.c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkShaderProgram* program = this->Quad->Program;
  if (!program || !program->GetCompiled())
  {
    return false;
  }
  auto* camera = vtkOpenGLCamera::SafeDownCast(renderer->GetActiveCamera());
  vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  camera->GetKeyMatrices(renderer, wcvc, normals, vcdc, wcdc);
  // The key matrices are transposed; the inverse of the key form is the key form of the inverse.
  vtkNew<vtkMatrix4x4> dcToWorld;
  vtkMatrix4x4::Invert(wcdc, dcToWorld);
  program->SetUniformMatrix("dcToWorld", dcToWorld);
  program->SetUniformMatrix("worldToClip", wcdc);
  program->SetUniformi("writeDepth", s.WriteDepth ? 1 : 0);
  const float size[2] = { static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform2f("viewportSize", size);
  const double* box = textures.Box();
  const float boxMin[3] = { static_cast<float>(box[0]), static_cast<float>(box[2]), static_cast<float>(box[4]) };
  const float boxMax[3] = { static_cast<float>(box[1]), static_cast<float>(box[3]), static_cast<float>(box[5]) };
  program->SetUniform3f("boxMin", boxMin);
  program->SetUniform3f("boxMax", boxMax);
  const float blocks[3] = { static_cast<float>(textures.BlockCount()[0]), static_cast<float>(textures.BlockCount()[1]),
                            static_cast<float>(textures.BlockCount()[2]) };
  program->SetUniform3f("blockCount", blocks);
  program->SetUniformf("extinction", static_cast<float>(s.Extinction));
  program->SetUniformf("lightExtinction", static_cast<float>(s.LightExtinction));
  program->SetUniformf("albedo", static_cast<float>(s.Albedo));
  program->SetUniformf("stepLength", static_cast<float>(s.StepLength));
  program->SetUniformi("maxSteps", s.MaxSteps);
  program->SetUniformf("minTransmittance", static_cast<float>(s.MinTransmittance));
  program->SetUniformf("emptyDensity", static_cast<float>(s.EmptyDensity));
  const float light[3] = { static_cast<float>(s.LightDirection[0]), static_cast<float>(s.LightDirection[1]),
                           static_cast<float>(s.LightDirection[2]) };
  program->SetUniform3f("lightDirection", light);
  const float lightColor[3] = { static_cast<float>(s.LightColor[0]), static_cast<float>(s.LightColor[1]),
                                static_cast<float>(s.LightColor[2]) };
  program->SetUniform3f("lightColor", lightColor);
  const float sky[3] = { static_cast<float>(s.SkyColor[0]), static_cast<float>(s.SkyColor[1]),
                         static_cast<float>(s.SkyColor[2]) };
  program->SetUniform3f("skyColor", sky);
  program->SetUniformf("anisotropy", static_cast<float>(s.Anisotropy));
  program->SetUniformi("shadows", s.Shadows && textures.Light() ? 1 : 0);
  program->SetUniformi("octaves", s.Octaves);
  program->SetUniformf("powder", static_cast<float>(s.Powder));
  program->SetUniformf("diffuseDecay",
                       static_cast<float>(std::sqrt(3.0 * (1.0 - s.Albedo) * (1.0 - std::abs(s.Anisotropy)))));
  program->SetUniformi("displayMode", s.DisplayMode);

  vtkTextureObject* light3D = textures.Light() ? textures.Light() : textures.Density();
  textures.Density()->Activate();
  program->SetUniformi("densityTex", textures.Density()->GetTextureUnit());
  light3D->Activate();
  program->SetUniformi("lightTex", light3D->GetTextureUnit());
  textures.Blocks()->Activate();
  program->SetUniformi("blockTex", textures.Blocks()->GetTextureUnit());
  this->OpaqueDepth->Activate();
  program->SetUniformi("opaqueDepthTex", this->OpaqueDepth->GetTextureUnit());

  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  state->vtkglViewport(x0, y0, width, height);
  if (s.WriteDepth)
  {
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_ALWAYS); // the march already stopped at the opaque depth
    state->vtkglDepthMask(GL_TRUE);
  }
  else
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
  }
  if (s.DisplayMode == 1)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    // Premultiplied: what is behind keeps its colour in proportion to the transmittance.
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  this->Quad->Render();
  this->OpaqueDepth->Deactivate();
  textures.Blocks()->Deactivate();
  light3D->Deactivate();
  textures.Density()->Deactivate();
  return true;
}

void CloudMarchPass::Release(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  if (this->OpaqueDepth)
  {
    this->OpaqueDepth->ReleaseGraphicsResources(window);
  }
}
} // namespace parafluid
