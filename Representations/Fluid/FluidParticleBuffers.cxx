#include "FluidParticleBuffers.h"

#include "FluidScreenTargets.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointSet.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace parafluid
{
void FluidParticleBuffers::Update(vtkOpenGLRenderWindow* window, vtkPointSet* input, vtkDataArray* radii, double radius,
                                  vtkUnsignedCharArray* colors, vtkMTimeType key)
{
  if (key == this->Key && (colors != nullptr) == this->Colored && this->ParticleTexture)
  {
    return;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<float> packed(static_cast<size_t>(4 * n));
  double maxRadius = 0.0;
  vtkMath::UninitializeBounds(this->CentreBounds);
  double box[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    double r = radii ? radii->GetComponent(i, 0) : radius;
    const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(r);
    if (!finite || r <= 0.0)
    {
      r = 0.0; // the vertex shader drops it: a NaN particle must not poison the picture
    }
    else
    {
      maxRadius = std::max(maxRadius, r);
      for (int k = 0; k < 3; ++k)
      {
        box[2 * k] = std::min(box[2 * k], x[k]);
        box[2 * k + 1] = std::max(box[2 * k + 1], x[k]);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      packed[4 * i + k] = finite ? static_cast<float>(x[k]) : 0.0f;
    }
    packed[4 * i + 3] = static_cast<float>(r);
  }
  if (maxRadius > 0.0)
  {
    std::copy(box, box + 6, this->CentreBounds);
  }
  if (!this->ParticleBuffer)
  {
    this->ParticleBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->ParticleBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    this->ParticleTexture = makeScreenTexture(window);
  }
  this->ParticleBuffer->Upload(packed, vtkOpenGLBufferObject::TextureBuffer);
  this->ParticleTexture->ReleaseGraphicsResources(window);
  this->ParticleTexture->CreateTextureBuffer(static_cast<unsigned int>(n), 4, VTK_FLOAT, this->ParticleBuffer);
  this->Colored = colors != nullptr;
  if (colors)
  {
    if (!this->ColorBuffer)
    {
      this->ColorBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
      this->ColorBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
      this->ColorTexture = makeScreenTexture(window);
    }
    // MapScalars gives 4 components for RGBA lookup tables and may give fewer otherwise.
    std::vector<unsigned char> rgba(static_cast<size_t>(4 * n), 255);
    const int nc = colors->GetNumberOfComponents();
    for (vtkIdType i = 0; i < n; ++i)
    {
      const unsigned char* c = colors->GetPointer(nc * i);
      for (int k = 0; k < 3; ++k)
      {
        rgba[4 * i + k] = c[nc >= 3 ? k : 0];
      }
    }
    this->ColorBuffer->Upload(rgba, vtkOpenGLBufferObject::TextureBuffer);
    this->ColorTexture->ReleaseGraphicsResources(window);
    this->ColorTexture->CreateTextureBuffer(static_cast<unsigned int>(n), 4, VTK_UNSIGNED_CHAR, this->ColorBuffer);
  }
  this->Uploaded = n;
  this->Radius = maxRadius;
  this->Key = key;
}

void FluidParticleBuffers::Release(vtkWindow* window)
{
  for (vtkTextureObject* t : { this->ParticleTexture.Get(), this->ColorTexture.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  for (vtkOpenGLBufferObject* b : { this->ParticleBuffer.Get(), this->ColorBuffer.Get() })
  {
    if (b)
    {
      b->ReleaseGraphicsResources();
    }
  }
  this->ParticleBuffer = this->ColorBuffer = nullptr;
  this->ParticleTexture = this->ColorTexture = nullptr;
  this->Key = 0;
}
} // namespace parafluid
