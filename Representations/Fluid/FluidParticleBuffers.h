#pragma once
// The particles on the GPU: centre and radius (float4) and optional RGBA8 colours as texture
// buffers the splat passes read, uploaded again only when the data, the radius or the colouring
// changed. NaN particles get radius 0 (the vertex shader drops them).
#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkDataArray;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkPointSet;
class vtkTextureObject;
class vtkUnsignedCharArray;
class vtkWindow;

namespace parafluid
{
class FluidParticleBuffers
{
public:
  /// Uploads `input` when `key` (an MTime) or whether there are colours changed. `radii`: a point
  /// array of radii, or null for `radius` everywhere; `colors`: one RGB(A) tuple per point or null.
  void Update(vtkOpenGLRenderWindow* window, vtkPointSet* input, vtkDataArray* radii, double radius,
              vtkUnsignedCharArray* colors, vtkMTimeType key);

  vtkTextureObject* Particles() const { return this->ParticleTexture; }
  vtkTextureObject* Colors() const { return this->ColorTexture; }
  bool HasColors() const { return this->Colored; }
  vtkIdType Count() const { return this->Uploaded; }
  /// Largest finite radius; 0 when no particle can be drawn.
  double MaxRadius() const { return this->Radius; }
  /// Of the finite particle centres.
  const double* Bounds() const { return this->CentreBounds; }

  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLBufferObject> ParticleBuffer, ColorBuffer;
  vtkSmartPointer<vtkTextureObject> ParticleTexture, ColorTexture;
  vtkMTimeType Key = 0;
  vtkIdType Uploaded = 0;
  double Radius = 0.0;
  bool Colored = false;
  double CentreBounds[6] = { 0, 0, 0, 0, 0, 0 };
};
} // namespace parafluid
