#include "vtkPFScreenSpaceFluidActor.h"

#include "vtkMapper.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkPFScreenSpaceFluidActor);

int vtkPFScreenSpaceFluidActor::RenderOverlay(vtkViewport* viewport)
{
  auto* renderer = vtkRenderer::SafeDownCast(viewport);
  if (!renderer || !this->Mapper || !this->GetVisibility())
  {
    return 0;
  }
  this->Mapper->Render(renderer, this);
  this->EstimatedRenderTime += this->Mapper->GetTimeToDraw();
  return 1;
}
