/**
 * @class vtkPFToonFluidRepresentation
 * @brief ParaView's "Toon Fluid" representation: the Screen-Space Fluid representation drawing
 * with a vtkPFToonFluidMapper (toon bands and ink lines), whose settings it forwards.
 */
#pragma once

#include "ParaFluidNPRRepresentationsModule.h"
#include "vtkPFScreenSpaceFluidRepresentation.h"

class vtkPFToonFluidMapper;

class PARAFLUIDNPRREPRESENTATIONS_EXPORT vtkPFToonFluidRepresentation : public vtkPFScreenSpaceFluidRepresentation
{
public:
  static vtkPFToonFluidRepresentation* New();
  vtkTypeMacro(vtkPFToonFluidRepresentation, vtkPFScreenSpaceFluidRepresentation);

  //@{
  /// Forwarded to vtkPFToonFluidMapper (see it for meanings and units).
  void SetToonBands(int bands);
  void SetLineColor(double r, double g, double b);
  void SetLineWidth(double pixels);
  void SetLineThreshold(double threshold);
  void SetDepthContourSpacing(double radii);
  //@}

protected:
  vtkPFToonFluidRepresentation();
  ~vtkPFToonFluidRepresentation() override;
  vtkPFToonFluidMapper* GetToonMapper() const;

private:
  vtkPFToonFluidRepresentation(const vtkPFToonFluidRepresentation&) = delete;
  void operator=(const vtkPFToonFluidRepresentation&) = delete;
};
