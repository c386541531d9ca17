#include "RainStreakPass.h"

#include "RainFrame.h"
#include "RainPointBuffer.h"
#include "RainStreakFS.h"
#include "RainStreakVS.h"

#include "parafluid/rain/DropTransfer.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

namespace parafluid
{
void RainStreakPass::EnsureRadiance(const RainFrame& frame, double refractiveIndex)
{
  const int rows = kTransferRows, width = kRadianceColumns;
  const bool newIndex = this->TransferTable.empty() || refractiveIndex != this->TransferIndex;
  if (newIndex)
  {
    // Computed once per refractive index: 400k rays over 9 interactions take about 0.1 s.
    rain::DropTransferSettings settings;
    settings.refractiveIndex = refractiveIndex;
    const rain::DropTransfer drop(settings);
    this->TransferTable = drop.transferTable(width, rows);
    this->TransferIndex = refractiveIndex;
  }
  if (!newIndex && this->RadianceTexture && frame.Environment == this->RadianceEnvironment)
  {
    return;
  }
  // The drop's radiance toward each view direction: its transfer vector dotted with the
  // environment's coefficients, once per environment (8192 directions x 16 coefficients), so
  // that a drop's colour is one texture read instead of four reads and 48 products per vertex.
  std::vector<float>& texels = this->RadianceTexels;
  texels.assign(static_cast<std::size_t>(width) * rows * 4, 0.0f);
  for (std::size_t direction = 0; direction < static_cast<std::size_t>(width) * rows; ++direction)
  {
    const float* t = &this->TransferTable[direction * rain::kSHCount];
    for (int c = 0; c < 3; ++c)
    {
      float sum = 0.0f;
      for (int k = 0; k < rain::kSHCount; ++k)
      {
        sum += t[k] * frame.Environment[static_cast<std::size_t>(c * 16 + k)];
      }
      texels[4 * direction + c] = std::max(sum, 0.0f);
    }
    texels[4 * direction + 3] = 1.0f;
  }
  if (!this->RadianceTexture)
  {
    this->RadianceTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->RadianceTexture->SetContext(frame.Window);
    this->RadianceTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->RadianceTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  this->RadianceTexture->ReleaseGraphicsResources(frame.Window);
  this->RadianceTexture->SetInternalFormat(GL_RGBA32F);
  this->RadianceTexture->SetFormat(GL_RGBA);
  this->RadianceTexture->SetDataType(GL_FLOAT);
  this->RadianceTexture->Create2DFromRaw(width, rows, 4, VTK_FLOAT, texels.data());
  this->RadianceEnvironment = frame.Environment;
}

const std::vector<float>& RainStreakPass::Radiance(const RainFrame& frame, double refractiveIndex)
{
  this->EnsureRadiance(frame, refractiveIndex);
  return this->RadianceTexels;
}

bool RainStreakPass::Run(const RainFrame& frame, const RainPointBuffer& drops, const Settings& settings)
{
  if (drops.Count() == 0 || !drops.Texture())
  {
    return true;
  }
  this->EnsureRadiance(frame, settings.RefractiveIndex);
  vtkOpenGLShaderCache* cache = frame.Window->GetShaderCache();
  if (!this->Program)
  {
    this->Program = cache->ReadyShaderProgram(RainStreakVS, RainStreakFS, "");
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
  drops.Texture()->Activate();
  this->RadianceTexture->Activate();
  vtkShaderProgram* program = this->Program;
  program->SetUniformi("drops", drops.Texture()->GetTextureUnit());
  program->SetUniformi("radiance", this->RadianceTexture->GetTextureUnit());
  program->SetUniformMatrix("WCVCMatrix", frame.WorldToView);
  program->SetUniformMatrix("VCDCMatrix", frame.ViewToClip);
  program->SetUniform2f("viewport", frame.Viewport);
  program->SetUniform3f("eye", frame.Eye);
  program->SetUniformf("widthScale", static_cast<float>(settings.WidthScale));
  program->SetUniformf("maxStreakArea", static_cast<float>(settings.MaxStreakArea));
  program->SetUniformf("brightness", static_cast<float>(settings.Brightness));
  program->SetUniformf("opacity", static_cast<float>(settings.Opacity));
  program->SetUniformf("fogDistance", static_cast<float>(settings.FogDistance));
  program->SetUniformi("radianceOnly", settings.RadianceOnly ? 1 : 0);

  vtkOpenGLState* state = frame.State;
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedCull(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDepthMask(settings.RadianceOnly ? GL_TRUE : GL_FALSE);
  if (settings.RadianceOnly)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  if (!this->EmptyVAO)
  {
    glGenVertexArrays(1, &this->EmptyVAO);
  }
  glBindVertexArray(this->EmptyVAO);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * drops.Count()));
  glBindVertexArray(0);
  this->RadianceTexture->Deactivate();
  drops.Texture()->Deactivate();
  return true;
}

void RainStreakPass::Release(vtkWindow* window)
{
  if (this->RadianceTexture)
  {
    this->RadianceTexture->ReleaseGraphicsResources(window);
    this->RadianceTexture = nullptr;
  }
  if (this->EmptyVAO)
  {
    glDeleteVertexArrays(1, &this->EmptyVAO);
    this->EmptyVAO = 0;
  }
  this->Program = nullptr;
}
} // namespace parafluid
