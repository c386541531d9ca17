#pragma once
// Points for the rain's passes in a texture buffer, two RGBA float texels each: (position, a) and
// (vector, b), read by index in the vertex shader (no vertex arrays). Uploaded only when the data
// changed.
#include "vtkOpenGLBufferObject.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkType.h"

#include <vector>

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace parafluid
{
class RainPointBuffer
{
public:
  /// `packed`: 8 floats per point. `key`: changes when the data does.
  void Update(vtkOpenGLRenderWindow* window, const std::vector<float>& packed, vtkMTimeType key);
  vtkTextureObject* Texture() const { return this->Buffer; }
  vtkIdType Count() const { return this->Points; }
  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLBufferObject> Data;
  vtkSmartPointer<vtkTextureObject> Buffer;
  vtkMTimeType Key = 0;
  vtkIdType Points = 0;
};
} // namespace parafluid
