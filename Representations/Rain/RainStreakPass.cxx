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

#include <vector>

namespace parafluid
{
void RainStreakPass::EnsureTransfer(const RainFrame& frame, double refractiveIndex)
{
  if (this->Transfer && refractiveIndex == this->TransferIndex)
  {
    return;
  }
  // Computed once per refractive index: 400k rays over 9 interactions take about 0.1 s.
  rain::DropTransferSettings settings;
  settings.refractiveIndex = refractiveIndex;
  const rain::DropTransfer drop(settings);
  const int rows = kTransferRows, width = 2 * kTransferRows;
  const std::vector<float> table = drop.transferTable(width, rows);
  // Four blocks of rows, block k holding coefficients 4k .. 4k + 3 as RGBA.
  std::vector<float> texels(static_cast<std::size_t>(width) * rows * 4 * 4);
  for (int block = 0; block < 4; ++block)
  {
    for (int row = 0; row < rows; ++row)
    {
      for (int col = 0; col < width; ++col)
      {
        const std::size_t direction = static_cast<std::size_t>(row) * width + col;
        const std::size_t texel = (static_cast<std::size_t>(block * rows + row) * width + col) * 4;
        for (int c = 0; c < 4; ++c)
        {
          texels[texel + c] = table[direction * rain::kSHCount + 4 * block + c];
        }
      }
    }
  }
  if (!this->Transfer)
  {
    this->Transfer = vtkSmartPointer<vtkTextureObject>::New();
    this->Transfer->SetContext(frame.Window);
    this->Transfer->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Transfer->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  this->Transfer->ReleaseGraphicsResources(frame.Window);
  this->Transfer->SetInternalFormat(GL_RGBA32F);
  this->Transfer->SetFormat(GL_RGBA);
  this->Transfer->SetDataType(GL_FLOAT);
  this->Transfer->Create2DFromRaw(width, 4 * rows, 4, VTK_FLOAT, texels.data());
  this->TransferIndex = refractiveIndex;
}

bool RainStreakPass::Run(const RainFrame& frame, const RainPointBuffer& drops, const Settings& settings)
{
  if (drops.Count() == 0 || !drops.Texture())
  {
    return true;
  }
  this->EnsureTransfer(frame, settings.RefractiveIndex);
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
  this->Transfer->Activate();
  vtkShaderProgram* program = this->Program;
  program->SetUniformi("drops", drops.Texture()->GetTextureUnit());
  program->SetUniformi("transfer", this->Transfer->GetTextureUnit());
  program->SetUniformi("transferRows", kTransferRows);
  program->SetUniformMatrix("WCVCMatrix", frame.WorldToView);
  program->SetUniformMatrix("VCDCMatrix", frame.ViewToClip);
  program->SetUniform2f("viewport", frame.Viewport);
  program->SetUniform3f("eye", frame.Eye);
  program->SetUniformf("widthScale", static_cast<float>(settings.WidthScale));
  program->SetUniformf("brightness", static_cast<float>(settings.Brightness));
  program->SetUniformf("opacity", static_cast<float>(settings.Opacity));
  program->SetUniformf("fogDistance", static_cast<float>(settings.FogDistance));
  program->SetUniformi("radianceOnly", settings.RadianceOnly ? 1 : 0);
  float environment[16][3];
  for (int k = 0; k < 16; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      environment[k][c] = frame.Environment[static_cast<std::size_t>(c * 16 + k)];
    }
  }
  program->SetUniform3fv("environment", 16, environment);

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
  this->Transfer->Deactivate();
  drops.Texture()->Deactivate();
  return true;
}

void RainStreakPass::Release(vtkWindow* window)
{
  if (this->Transfer)
  {
    this->Transfer->ReleaseGraphicsResources(window);
  }
  this->TransferIndex = 0.0;
  if (this->EmptyVAO)
  {
    glDeleteVertexArrays(1, &this->EmptyVAO);
    this->EmptyVAO = 0;
  }
  this->Program = nullptr;
}
} // namespace parafluid
