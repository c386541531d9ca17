#include "RainSplashPass.h"

#include "RainFrame.h"
#include "RainPointBuffer.h"
#include "RainSplashFS.h"
#include "RainSplashVS.h"

#include "parafluid/rain/SplashSprites.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace parafluid
{
bool RainSplashPass::Run(const RainFrame& frame, const RainPointBuffer& splashes, const Settings& settings)
{
  if (splashes.Count() == 0 || !splashes.Texture())
  {
    return true;
  }
  if (!this->Atlas)
  {
    const int size = 64;
    const auto atlas = rain::splashAtlas(size);
    this->Atlas = vtkSmartPointer<vtkTextureObject>::New();
    this->Atlas->SetContext(frame.Window);
    this->Atlas->SetMinificationFilter(vtkTextureObject::Linear);
    this->Atlas->SetMagnificationFilter(vtkTextureObject::Linear);
    this->Atlas->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Atlas->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Atlas->Create2DFromRaw(rain::kSplashFrames * size, rain::kSplashSequences * size, 4, VTK_UNSIGNED_CHAR,
                                 const_cast<std::uint8_t*>(atlas.data()));
  }
  vtkOpenGLShaderCache* cache = frame.Window->GetShaderCache();
  if (!this->Program)
  {
    this->Program = cache->ReadyShaderProgram(RainSplashVS, RainSplashFS, "");
  }
  else
  {
    cache->ReadyShaderProgram(this->Program);
  }
  if (!this->Program || !this->Program->GetCompiled())
  {
    this->Program = nullptr;
    return false;
  }
  splashes.Texture()->Activate();
  this->Atlas->Activate();
  vtkShaderProgram* program = this->Program;
  program->SetUniformi("splashes", splashes.Texture()->GetTextureUnit());
  program->SetUniformi("atlas", this->Atlas->GetTextureUnit());
  program->SetUniformMatrix("WCVCMatrix", frame.WorldToView);
  program->SetUniformMatrix("VCDCMatrix", frame.ViewToClip);
  program->SetUniform3f("eye", frame.Eye);
  program->SetUniformf("splashSize", static_cast<float>(settings.SplashSize));
  program->SetUniformf("lifetime", static_cast<float>(settings.Lifetime));
  program->SetUniformf("brightness", static_cast<float>(settings.Brightness));
  program->SetUniformf("opacity", static_cast<float>(settings.Opacity));
  program->SetUniform3f("ambient", settings.Ambient);

  vtkOpenGLState* state = frame.State;
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedCull(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (!this->EmptyVAO)
  {
    glGenVertexArrays(1, &this->EmptyVAO);
  }
  glBindVertexArray(this->EmptyVAO);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * splashes.Count()));
  glBindVertexArray(0);
  this->Atlas->Deactivate();
  splashes.Texture()->Deactivate();
  return true;
}

void RainSplashPass::Release(vtkWindow* window)
{
  if (this->Atlas)
  {
    this->Atlas->ReleaseGraphicsResources(window);
    this->Atlas = nullptr;
  }
  if (this->EmptyVAO)
  {
    glDeleteVertexArrays(1, &this->EmptyVAO);
    this->EmptyVAO = 0;
  }
  this->Program = nullptr;
}
} // namespace parafluid
