/**
 * @class vtkPFRayMarchedFluidRepresentation
 * @brief ParaView's "Ray-Marched Fluid" representation: the Screen-Space Fluid representation's
 * delivery, colouring and appearance, drawn by a vtkPFRayMarchedFluidMapper, whose settings it
 * forwards.
 */
#pragma once

#include "ParaFluidFluidRepresentationsModule.h"
#include "vtkPFScreenSpaceFluidRepresentation.h"

class vtkPFRayMarchedFluidMapper;

class PARAFLUIDFLUIDREPRESENTATIONS_EXPORT vtkPFRayMarchedFluidRepresentation
  : public vtkPFScreenSpaceFluidRepresentation
{
public:
  static vtkPFRayMarchedFluidRepresentation* New();
  vtkTypeMacro(vtkPFRayMarchedFluidRepresentation, vtkPFScreenSpaceFluidRepresentation);

  //@{
  /// Particle spacing d [world units]; 0: the particle_spacing field value, else the mean spacing
  /// the bounds and the point count imply.
  void SetParticleSpacing(double spacing);
  /// Forwarded to vtkPFRayMarchedFluidMapper (see it for meanings and units).
  void SetKernelRadius(double spacings);
  void SetIsoValue(double value);
  void SetStepSize(double spacings);
  void SetMaxSteps(int steps);
  void SetResolutionScale(double scale);
  void SetEmptySpaceSkipping(bool skip);
  void SetStartStopSplats(bool splats);
  //@}

  vtkPFRayMarchedFluidMapper* GetRayMarchedMapper() const;

protected:
  vtkPFRayMarchedFluidRepresentation();
  ~vtkPFRayMarchedFluidRepresentation() override;

private:
  vtkPFRayMarchedFluidRepresentation(const vtkPFRayMarchedFluidRepresentation&) = delete;
  void operator=(const vtkPFRayMarchedFluidRepresentation&) = delete;
};
