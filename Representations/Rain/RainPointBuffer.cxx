#include "RainPointBuffer.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

namespace parafluid
{
void RainPointBuffer::Update(vtkOpenGLRenderWindow* window, const std::vector<float>& packed, vtkMTimeType key)
{
  if (this->Buffer && key == this->Key)
  {
    return;
  }
  this->Key = key;
  this->Points = static_cast<vtkIdType>(packed.size() / 8);
  if (!this->Data)
  {
    this->Data = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Data->SetType(vtkOpenGLBufferObject::TextureBuffer);
    this->Buffer = vtkSmartPointer<vtkTextureObject>::New();
    this->Buffer->SetContext(window);
  }
  // An empty buffer cannot back a texture: one unused texel pair keeps the sampler valid.
  std::vector<float> data = packed.empty() ? std::vector<float>(8, 0.0f) : packed;
  this->Data->Upload(data, vtkOpenGLBufferObject::TextureBuffer);
  this->Buffer->ReleaseGraphicsResources(window);
  this->Buffer->CreateTextureBuffer(static_cast<unsigned int>(data.size() / 4), 4, VTK_FLOAT, this->Data);
}

void RainPointBuffer::Release(vtkWindow* window)
{
  if (this->Buffer)
  {
    this->Buffer->ReleaseGraphicsResources(window);
  }
  if (this->Data)
  {
    this->Data->ReleaseGraphicsResources();
  }
  this->Key = 0;
}
} // namespace parafluid
