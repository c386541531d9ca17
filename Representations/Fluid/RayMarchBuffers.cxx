#include "RayMarchBuffers.h"

#include "FluidScreenTargets.h"

#include "vtkMath.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointSet.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace parafluid
{
namespace
{
/// `data` (at least one element: an empty buffer cannot back a texture) into slot i's buffer texture.
template<typename T>
void upload(vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkOpenGLBufferObject>& buffer,
            vtkSmartPointer<vtkTextureObject>& texture, std::vector<T> data, int components, int vtkType,
            unsigned int internalFormat)
{
  if (data.empty())
  {
    data.assign(components, T(0));
  }
  if (!buffer)
  {
    buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    texture = makeScreenTexture(window);
  }
  buffer->Upload(data, vtkOpenGLBufferObject::TextureBuffer);
  texture->ReleaseGraphicsResources(window);
  texture->SetInternalFormat(internalFormat);
  texture->CreateTextureBuffer(static_cast<unsigned int>(data.size() / components), components, vtkType, buffer);
}
} // namespace

void RayMarchBuffers::Update(vtkOpenGLRenderWindow* window, vtkPointSet* input, double spacing, double kernelRadius,
                             double isoValue, vtkUnsignedCharArray* colors, vtkMTimeType key)
{
  const double settings[3] = { spacing, kernelRadius, isoValue };
  if (this->Textures[0] && key == this->Key && std::equal(settings, settings + 3, this->Settings) &&
      (colors != nullptr) == this->Colored)
  {
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<float> xyz(static_cast<std::size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      xyz[3 * i + k] = static_cast<float>(x[k]);
    }
  }
  this->Cells.build(xyz.data(), static_cast<std::size_t>(n), spacing, kernelRadius, isoValue);
  vtkMath::UninitializeBounds(this->CentreBounds);
  const std::vector<float>& sorted = this->Cells.sortedPositions();
  if (!sorted.empty())
  {
    double box[6] = {
      VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX
    };
    for (std::size_t s = 0; s < sorted.size() / 4; ++s)
    {
      for (int k = 0; k < 3; ++k)
      {
        box[2 * k] = std::min(box[2 * k], static_cast<double>(sorted[4 * s + k]));
        box[2 * k + 1] = std::max(box[2 * k + 1], static_cast<double>(sorted[4 * s + k]));
      }
    }
    std::copy(box, box + 6, this->CentreBounds);
  }
  upload(window, this->Buffers[0], this->Textures[0], sorted, 4, VTK_FLOAT, GL_RGBA32F);
  upload(window, this->Buffers[1], this->Textures[1], this->Cells.cellStart(), 1, VTK_UNSIGNED_INT, GL_R32UI);
  const std::vector<std::uint8_t>& blocks = this->Cells.blockOccupied();
  upload(window, this->Buffers[2], this->Textures[2], std::vector<std::uint32_t>(blocks.begin(), blocks.end()), 1,
         VTK_UNSIGNED_INT, GL_R32UI);
  upload(window, this->Buffers[4], this->Textures[4], this->Cells.splatCells(), 4, VTK_FLOAT, GL_RGBA32F);
  this->Colored = colors != nullptr;
  if (colors)
  {
    // MapScalars gives 4 components for RGBA lookup tables and may give fewer otherwise.
    const std::vector<std::uint32_t>& order = this->Cells.order();
    std::vector<unsigned char> rgba(4 * order.size(), 255);
    const int nc = colors->GetNumberOfComponents();
    for (std::size_t s = 0; s < order.size(); ++s)
    {
      const unsigned char* c = colors->GetPointer(nc * static_cast<vtkIdType>(order[s]));
      for (int k = 0; k < 3; ++k)
      {
        rgba[4 * s + k] = c[nc >= 3 ? k : 0];
      }
    }
    upload(window, this->Buffers[3], this->Textures[3], rgba, 4, VTK_UNSIGNED_CHAR, GL_RGBA8);
  }
  std::copy(settings, settings + 3, this->Settings);
  this->Key = key;
  this->BuildMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void RayMarchBuffers::Release(vtkWindow* window)
{
  for (int i = 0; i < 5; ++i)
  {
    if (this->Textures[i])
    {
      this->Textures[i]->ReleaseGraphicsResources(window);
    }
    if (this->Buffers[i])
    {
      this->Buffers[i]->ReleaseGraphicsResources();
    }
    this->Textures[i] = nullptr;
    this->Buffers[i] = nullptr;
  }
  this->Key = 0;
}
} // namespace parafluid
