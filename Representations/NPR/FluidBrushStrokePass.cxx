#include "FluidBrushStrokePass.h"

#include "FluidScreenCommon.h"
#include "FluidStrokeFS.h"
#include "FluidStrokeVS.h"
#include "parafluid/npr/BrushStrokes.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace parafluid
{
void FluidBrushStrokePass::Upload(vtkOpenGLRenderWindow* window, const npr::BrushStrokeSet& strokes,
                                  const std::vector<float>& rgb)
{
  // Three texels per segment: (start, fraction), (end, fraction), (colour, seed hash).
  std::vector<float> texels;
  for (std::size_t s = 0; s < strokes.strokeCount(); ++s)
  {
    const std::uint32_t first = strokes.offsets[s], last = strokes.offsets[s + 1];
    std::vector<double> fraction(last - first, 0.0);
    for (std::uint32_t q = first + 1; q < last; ++q)
    {
      const float* a = &strokes.points[3 * (q - 1)];
      const float* b = &strokes.points[3 * q];
      fraction[q - first] =
        fraction[q - first - 1] +
        std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
    }
    const double total = fraction.back();
    if (!(total > 0.0))
    {
      continue; // a stroke that does not go anywhere has no direction to paint along
    }
    // The shader hashes the seed with sin(): small numbers keep it well mixed in float.
    const auto seed = static_cast<float>(strokes.seed[s] % 997u);
    for (std::uint32_t q = first + 1; q < last; ++q)
    {
      const float* a = &strokes.points[3 * (q - 1)];
      const float* b = &strokes.points[3 * q];
      texels.insert(texels.end(), { a[0], a[1], a[2], static_cast<float>(fraction[q - 1 - first] / total), b[0], b[1],
                                    b[2], static_cast<float>(fraction[q - first] / total), rgb[3 * s], rgb[3 * s + 1],
                                    rgb[3 * s + 2], seed });
    }
  }
  this->Strokes = strokes.strokeCount();
  this->Segments = texels.size() / 12;
  if (this->Segments == 0)
  {
    return;
  }
  if (!this->Buffer)
  {
    this->Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    this->Texture = vtkSmartPointer<vtkTextureObject>::New();
    this->Texture->SetContext(window);
  }
  this->Buffer->Upload(texels, vtkOpenGLBufferObject::TextureBuffer);
  this->Texture->ReleaseGraphicsResources(window);
  this->Texture->CreateTextureBuffer(static_cast<unsigned int>(texels.size() / 4), 4, VTK_FLOAT, this->Buffer);
}

bool FluidBrushStrokePass::Draw(vtkOpenGLRenderWindow* window, const View& view, vtkTextureObject* depth,
                                unsigned int emptyVAO, double widthPixels, double hideDepth)
{
  if (this->Segments == 0)
  {
    return true;
  }
  if (!this->Program)
  {
    const std::string fs = std::string("//VTK::System::Dec\n") + FluidScreenCommon + FluidStrokeFS;
    this->Program = window->GetShaderCache()->ReadyShaderProgram(FluidStrokeVS, fs.c_str(), "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Program);
  }
  if (!this->Program)
  {
    return false;
  }
  vtkShaderProgram* program = this->Program;
  this->Texture->Activate();
  depth->Activate();
  const float size[2] = { static_cast<float>(view.Size[0]), static_cast<float>(view.Size[1]) };
  program->SetUniformi("strokes", this->Texture->GetTextureUnit());
  program->SetUniformi("depthTex", depth->GetTextureUnit());
  program->SetUniformMatrix("MCVCMatrix", view.MCVC);
  program->SetUniformMatrix("VCDCMatrix", view.VCDC);
  program->SetUniform2f("viewportSize", size);
  program->SetUniform2i("viewportOrigin", view.Origin);
  program->SetUniform2i("rectMin", view.RectMin);
  program->SetUniform2i("rectMax", view.RectMax);
  program->SetUniformi("parallelProjection", view.Parallel ? 1 : 0);
  program->SetUniform4f("projection", view.Projection);
  program->SetUniformf("halfWidth", static_cast<float>(0.5 * widthPixels));
  program->SetUniformf("hideDepth", static_cast<float>(hideDepth));
  // About one bristle per 1.5 pixels of width, at least 3.
  program->SetUniformf("bristles", static_cast<float>(std::max(3.0, std::floor(widthPixels / 1.5))));
  glBindVertexArray(emptyVAO);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * this->Segments));
  glBindVertexArray(0);
  depth->Deactivate();
  this->Texture->Deactivate();
  return true;
}

void FluidBrushStrokePass::Release(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  if (this->Buffer)
  {
    this->Buffer->ReleaseGraphicsResources();
  }
  this->Strokes = this->Segments = 0;
  this->Program = nullptr; // the cache releases its programs with the window
}
} // namespace parafluid
