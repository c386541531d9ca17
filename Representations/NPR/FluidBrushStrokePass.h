/**
 * FluidBrushStrokePass: draws brush strokes (parafluid::npr::BrushStrokeSet) over the shaded
 * screen-space fluid, kept to its footprint and its visible surface (FluidStrokeVS/FS.glsl).
 * Owned by vtkPFScreenSpaceFluidMapper; not a VTK class and not wrapped.
 */
#pragma once

#include "vtkSmartPointer.h"

#include <cstddef>
#include <vector>

class vtkMatrix4x4;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
namespace npr
{
struct BrushStrokeSet;
}

class FluidBrushStrokePass
{
public:
  /// The strokes to the GPU as segments; rgb holds one colour (0..1) per stroke.
  void Upload(vtkOpenGLRenderWindow* window, const npr::BrushStrokeSet& strokes, const std::vector<float>& rgb);
  std::size_t StrokeCount() const { return this->Strokes; }
  std::size_t SegmentCount() const { return this->Segments; }

  struct View
  {
    vtkMatrix4x4* MCVC; // VTK key matrices (transposed, as given to SetUniformMatrix)
    vtkMatrix4x4* VCDC;
    int Size[2];                // viewport, pixels
    int Origin[2];              // its first pixel in the framebuffer
    int RectMin[2], RectMax[2]; // the fluid's rectangle in the depth target
    bool Parallel;
    float Projection[4];
  };
  /// Draws into the bound framebuffer with `depth` (eye distance of the smoothed surface) bound
  /// for the footprint test; the caller sets viewport, scissor, depth test and blending.
  /// `emptyVAO` is a vertex array without attributes. False when the shader did not build.
  bool Draw(vtkOpenGLRenderWindow* window, const View& view, vtkTextureObject* depth, unsigned int emptyVAO,
            double widthPixels, double hideDepth);

  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkShaderProgram* Program = nullptr; // owned by the window's shader cache
  std::size_t Strokes = 0;
  std::size_t Segments = 0;
};
} // namespace parafluid
