#include "vtkPFRayMarchedFluidRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPFRayMarchedFluidMapper.h"
#include "vtkSmartPointer.h"

#include <cmath>

vtkStandardNewMacro(vtkPFRayMarchedFluidRepresentation);

vtkPFRayMarchedFluidRepresentation::vtkPFRayMarchedFluidRepresentation()
{
  this->UseMapper(vtkSmartPointer<vtkPFRayMarchedFluidMapper>::New());
}

vtkPFRayMarchedFluidRepresentation::~vtkPFRayMarchedFluidRepresentation() = default;

vtkPFRayMarchedFluidMapper* vtkPFRayMarchedFluidRepresentation::GetRayMarchedMapper() const
{
  return static_cast<vtkPFRayMarchedFluidMapper*>(this->GetMapper());
}

void vtkPFRayMarchedFluidRepresentation::SetParticleSpacing(double spacing)
{
  if (!std::isfinite(spacing))
  {
    vtkWarningMacro(<< "ParticleSpacing = " << spacing << " is ignored: it must be a finite number (0: automatic)");
    return;
  }
  // The delivered radius is 0.6 d (automatic from the field data or the bounds when 0), and the
  // mapper takes d = radius / 0.6: one place decides the spacing.
  this->SetParticleRadius(spacing > 0.0 ? 0.6 * spacing : 0.0);
}

void vtkPFRayMarchedFluidRepresentation::SetKernelRadius(double spacings)
{
  this->GetRayMarchedMapper()->SetKernelRadius(spacings);
}

void vtkPFRayMarchedFluidRepresentation::SetIsoValue(double value)
{
  this->GetRayMarchedMapper()->SetIsoValue(value);
}

void vtkPFRayMarchedFluidRepresentation::SetStepSize(double spacings)
{
  this->GetRayMarchedMapper()->SetStepSize(spacings);
}

void vtkPFRayMarchedFluidRepresentation::SetMaxSteps(int steps)
{
  this->GetRayMarchedMapper()->SetMaxSteps(steps);
}

void vtkPFRayMarchedFluidRepresentation::SetResolutionScale(double scale)
{
  this->GetRayMarchedMapper()->SetResolutionScale(scale);
}

void vtkPFRayMarchedFluidRepresentation::SetEmptySpaceSkipping(bool skip)
{
  this->GetRayMarchedMapper()->SetEmptySpaceSkipping(skip);
}

void vtkPFRayMarchedFluidRepresentation::SetStartStopSplats(bool splats)
{
  this->GetRayMarchedMapper()->SetStartStopSplats(splats);
}
