#pragma once
// The ray-marched fluid's particles on the GPU: parafluid::surface::DensityCellGrid built on the CPU
// when the particles or the field's settings change, and its tables as texture buffers the march
// reads: sorted positions (RGBA32F), each cell's first slot with its occupancy bit (R32UI), the
// blocks' occupancy (R32UI), the cells splatted for the start/stop depths (RGBA32F) and, when
// colouring by an array, the sorted colours (RGBA8).
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include "parafluid/surface/DensityCellGrid.h"

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkPointSet;
class vtkTextureObject;
class vtkUnsignedCharArray;
class vtkWindow;

namespace parafluid
{
class RayMarchBuffers
{
public:
  /// The field of `input`: spacing d [world units], kernel support kernelRadius [world units], iso
  /// value. Rebuilt and uploaded only when `key` (an MTime) or a setting changed.
  void Update(vtkOpenGLRenderWindow* window, vtkPointSet* input, double spacing, double kernelRadius, double isoValue,
              vtkUnsignedCharArray* colors, vtkMTimeType key);

  const surface::DensityCellGrid& Grid() const { return this->Cells; }
  vtkTextureObject* Particles() const { return this->Textures[0]; }
  vtkTextureObject* CellStart() const { return this->Textures[1]; }
  vtkTextureObject* Blocks() const { return this->Textures[2]; }
  vtkTextureObject* Colors() const { return this->Colored ? this->Textures[3].Get() : nullptr; }
  vtkTextureObject* SplatCells() const { return this->Textures[4]; }
  /// Of the finite particle centres (uninitialised when there are none).
  const double* Bounds() const { return this->CentreBounds; }
  /// CPU time of the last rebuild (sort, occupancy and upload) [ms].
  double LastBuildMilliseconds() const { return this->BuildMilliseconds; }

  void Release(vtkWindow* window);

private:
  surface::DensityCellGrid Cells;
  vtkSmartPointer<vtkOpenGLBufferObject> Buffers[5];
  vtkSmartPointer<vtkTextureObject> Textures[5];
  vtkMTimeType Key = 0;
  double Settings[3] = { 0, 0, 0 };
  bool Colored = false;
  double CentreBounds[6] = { 0, 0, 0, 0, 0, 0 };
  double BuildMilliseconds = 0.0;
};
} // namespace parafluid
