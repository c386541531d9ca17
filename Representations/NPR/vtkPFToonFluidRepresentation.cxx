#include "vtkPFToonFluidRepresentation.h"

#include "vtkPFToonFluidMapper.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkPFToonFluidRepresentation);

vtkPFToonFluidRepresentation::vtkPFToonFluidRepresentation()
{
  vtkNew<vtkPFToonFluidMapper> mapper;
  this->UseMapper(mapper);
}

vtkPFToonFluidRepresentation::~vtkPFToonFluidRepresentation() = default;

vtkPFToonFluidMapper* vtkPFToonFluidRepresentation::GetToonMapper() const
{
  return vtkPFToonFluidMapper::SafeDownCast(this->GetMapper());
}

void vtkPFToonFluidRepresentation::SetToonBands(int bands)
{
  this->GetToonMapper()->SetToonBands(bands);
}
void vtkPFToonFluidRepresentation::SetLineColor(double r, double g, double b)
{
  this->GetToonMapper()->SetLineColor(r, g, b);
}
void vtkPFToonFluidRepresentation::SetLineWidth(double pixels)
{
  this->GetToonMapper()->SetLineWidth(pixels);
}
void vtkPFToonFluidRepresentation::SetLineThreshold(double threshold)
{
  this->GetToonMapper()->SetLineThreshold(threshold);
}
void vtkPFToonFluidRepresentation::SetDepthContourSpacing(double radii)
{
  this->GetToonMapper()->SetDepthContourSpacing(radii);
}
