/**
 * @class vtkPFBrushStrokeFluidRepresentation
 * @brief ParaView's "Brush Stroke Fluid" representation: the Screen-Space Fluid representation
 * drawing with a vtkPFBrushStrokeFluidMapper (toon bands painted over with strokes along the
 * flow), whose settings it forwards. Under MPI each process paints its own piece.
 */
#pragma once

#include "ParaFluidNPRRepresentationsModule.h"
#include "vtkPFToonFluidRepresentation.h"

class vtkPFBrushStrokeFluidMapper;

class PARAFLUIDNPRREPRESENTATIONS_EXPORT vtkPFBrushStrokeFluidRepresentation : public vtkPFToonFluidRepresentation
{
public:
  static vtkPFBrushStrokeFluidRepresentation* New();
  vtkTypeMacro(vtkPFBrushStrokeFluidRepresentation, vtkPFToonFluidRepresentation);

  //@{
  /// Forwarded to vtkPFBrushStrokeFluidMapper (see it for meanings and units).
  void SetStrokeWidth(double pixels);
  void SetStrokeLength(double radii);
  void SetStrokeSeedStride(int stride);
  void SetStrokeDuration(double seconds);
  void SetMaxStrokes(int count);
  void SetStrokeVelocityArray(const char* name);
  void SetStrokeColorArray(const char* name);
  //@}

protected:
  vtkPFBrushStrokeFluidRepresentation();
  ~vtkPFBrushStrokeFluidRepresentation() override;
  vtkPFBrushStrokeFluidMapper* GetStrokeMapper() const;

private:
  vtkPFBrushStrokeFluidRepresentation(const vtkPFBrushStrokeFluidRepresentation&) = delete;
  void operator=(const vtkPFBrushStrokeFluidRepresentation&) = delete;
};
