#pragma once
// The ray-marched fluid's start/stop depth maps from splats (after Xiao et al. 2017): the grid
// cells of the particles that can bound the surface, each box grown by the kernel's radius (it
// holds its particles' kernel spheres), drawn onto a coarse target (one pixel per BoundsPixels
// march pixels each way) that keeps, per pixel, the nearest and farthest view depth of the boxes
// over it, for splash and bulk apart (RayMarchBoundsVS.glsl, RayMarchBoundsFS.glsl). The march (RayMarchFS.glsl) then
// samples only between those depths: no ray where no sphere lies, and a ray through spray jumps from the spray's far
// side to the bulk.
#include "FluidScreenQuad.h" // the passes' shared declarations

#include "vtkSmartPointer.h"

class vtkShaderProgram;
class vtkTextureObject;
namespace parafluid
{
class RayMarchBuffers;

class RayMarchBoundsPass
{
public:
  static constexpr int BoundsPixels = 4; // march pixels per coarse pixel, each way

  /// Fills Bounds() for a march of `marchSize` pixels, each `pixelScale` viewport pixels wide.
  /// `separateSplash` false puts every particle in the bulk's pair (for comparison). Leaves the
  /// frame's framebuffer bound as it found it. False when the programs did not build.
  bool Run(FluidFrame& frame, const RayMarchBuffers& buffers, unsigned int emptyVAO, const int marchSize[2],
           double pixelScale, bool separateSplash);
  /// RGBA32F: splash nearest, -splash farthest, bulk nearest, -bulk farthest [view depth];
  /// 1e30 where no sphere lies.
  vtkTextureObject* Bounds() const { return this->Target; }
  void Release(vtkWindow* window);

private:
  vtkShaderProgram* Program = nullptr; // the shader cache owns it
  vtkSmartPointer<vtkTextureObject> Target;
};
} // namespace parafluid
