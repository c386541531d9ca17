#include "vtkPFBrushStrokeFluidRepresentation.h"

#include "vtkPFBrushStrokeFluidMapper.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkPFBrushStrokeFluidRepresentation);

vtkPFBrushStrokeFluidRepresentation::vtkPFBrushStrokeFluidRepresentation()
{
  vtkNew<vtkPFBrushStrokeFluidMapper> mapper;
  this->UseMapper(mapper);
}

vtkPFBrushStrokeFluidRepresentation::~vtkPFBrushStrokeFluidRepresentation() = default;

vtkPFBrushStrokeFluidMapper* vtkPFBrushStrokeFluidRepresentation::GetStrokeMapper() const
{
  return vtkPFBrushStrokeFluidMapper::SafeDownCast(this->GetMapper());
}

void vtkPFBrushStrokeFluidRepresentation::SetStrokeWidth(double pixels)
{
  this->GetStrokeMapper()->SetStrokeWidth(pixels);
}
void vtkPFBrushStrokeFluidRepresentation::SetStrokeLength(double radii)
{
  this->GetStrokeMapper()->SetStrokeLength(radii);
}
void vtkPFBrushStrokeFluidRepresentation::SetStrokeSeedStride(int stride)
{
  this->GetStrokeMapper()->SetStrokeSeedStride(stride);
}
void vtkPFBrushStrokeFluidRepresentation::SetStrokeDuration(double seconds)
{
  this->GetStrokeMapper()->SetStrokeDuration(seconds);
}
void vtkPFBrushStrokeFluidRepresentation::SetMaxStrokes(int count)
{
  this->GetStrokeMapper()->SetMaxStrokes(count);
}
void vtkPFBrushStrokeFluidRepresentation::SetStrokeVelocityArray(const char* name)
{
  this->GetStrokeMapper()->SetStrokeVelocityArray(name);
}
void vtkPFBrushStrokeFluidRepresentation::SetStrokeColorArray(const char* name)
{
  this->GetStrokeMapper()->SetStrokeColorArray(name);
}
