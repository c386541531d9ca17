#include "vtkPFToonFluidMapper.h"

#include "FluidShadePass.h"
#include "FluidToonLinePass.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkPFToonFluidMapper);

vtkPFToonFluidMapper::vtkPFToonFluidMapper()
  : Lines(new parafluid::FluidToonLinePass)
{
  // The opaque surface's passes (no thickness, no refraction), shaded as a toon.
  this->SetDisplayMode(OpaqueSurface);
  // Bands quantise the normals: the styles keep the smoothing they were drawn with (4 radii,
  // cut at MaxFilterRadius pixels); spread taps streak the bands at grazing angles.
  this->SetFilterSize(4.0);
  this->SetSpreadFilterTaps(false);
  this->SetSmoothSilhouettes(false);
}

vtkPFToonFluidMapper::~vtkPFToonFluidMapper() = default;

void vtkPFToonFluidMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ToonBands: " << this->ToonBands << "\n";
  os << indent << "LineWidth: " << this->LineWidth << "\n";
}

void vtkPFToonFluidMapper::RunStylePasses(parafluid::FluidFrame& frame, parafluid::FluidScreenTargets& targets,
                                          int depth)
{
  this->Lines->Run(frame, targets, depth, { this->GetDepthRange(), this->LineWidth, this->LineThreshold });
}

void vtkPFToonFluidMapper::FillShading(parafluid::FluidShadeSettings& shading) const
{
  this->Superclass::FillShading(shading);
  shading.DisplayMode = Toon;
  shading.ToonBands = this->ToonBands;
  std::copy(this->LineColor, this->LineColor + 3, shading.LineColor);
  shading.DepthContourSpacing = this->DepthContourSpacing;
}

void vtkPFToonFluidMapper::ReleaseStyle(vtkWindow* window)
{
  this->Lines->Release(window);
}
