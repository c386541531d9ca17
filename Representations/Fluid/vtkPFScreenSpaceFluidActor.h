/**
 * @class vtkPFScreenSpaceFluidActor
 * @brief The prop of a vtkPFScreenSpaceFluidMapper: draws it after the rest of the scene.
 *
 * Screen-space fluid refracts and occludes what is behind it, so it has to run once the opaque,
 * translucent and volumetric geometry is in the framebuffer. Renderers draw props' overlays
 * last, so this actor draws its fluid there and nothing in the other stages. (A vtkVolume would
 * run before overlays too, but ParaView's depth peeling for volumes would render it once per
 * peel into the peeling buffers.)
 */
#pragma once

#include "ParaFluidFluidRepresentationsModule.h"
#include "vtkOpenGLActor.h"

class PARAFLUIDFLUIDREPRESENTATIONS_EXPORT vtkPFScreenSpaceFluidActor : public vtkOpenGLActor
{
public:
  static vtkPFScreenSpaceFluidActor* New();
  vtkTypeMacro(vtkPFScreenSpaceFluidActor, vtkOpenGLActor);

  int RenderOpaqueGeometry(vtkViewport*) override { return 0; }
  int RenderTranslucentPolygonalGeometry(vtkViewport*) override { return 0; }
  int RenderVolumetricGeometry(vtkViewport*) override { return 0; }
  vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }
  vtkTypeBool HasOpaqueGeometry() override { return 0; }
  int RenderOverlay(vtkViewport* viewport) override;

protected:
  vtkPFScreenSpaceFluidActor() = default;
  ~vtkPFScreenSpaceFluidActor() override = default;

private:
  vtkPFScreenSpaceFluidActor(const vtkPFScreenSpaceFluidActor&) = delete;
  void operator=(const vtkPFScreenSpaceFluidActor&) = delete;
};
