/**
 * @class vtkPFScreenSpaceFluidRepresentation
 * @brief ParaView's "Screen-Space Fluid" representation: particles drawn as a smooth liquid.
 *
 * Delivers the input's points (composite inputs merged; any dataset's points, with a warning when
 * it has cells other than vertices) to a vtkPFScreenSpaceFluidMapper drawn by a
 * vtkPFScreenSpaceFluidActor, and forwards the settings. Under MPI the pieces are gathered on
 * process 0, which draws the fluid over the opaque scene of every process (FluidSharedScene);
 * ParaView then composites the processes' images by depth.
 */
#pragma once

#include "ParaFluidFluidRepresentationsModule.h"
#include "vtkPVDataRepresentation.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>

class vtkPFScreenSpaceFluidActor;
class vtkPFScreenSpaceFluidMapper;
class vtkPolyData;
class vtkScalarsToColors;
namespace parafluid
{
class Communicator;
}

class PARAFLUIDFLUIDREPRESENTATIONS_EXPORT vtkPFScreenSpaceFluidRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkPFScreenSpaceFluidRepresentation* New();
  vtkTypeMacro(vtkPFScreenSpaceFluidRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;
  void SetVisibility(bool visible) override;

  //@{
  /// Colouring by a point array (ParaView's colouring controls).
  void SetLookupTable(vtkScalarsToColors* lut);
  void SetMapScalars(int map);
  //@}

  //@{
  /// Actor placement (ParaView's transform controls).
  void SetPosition(double x, double y, double z);
  void SetScale(double x, double y, double z);
  void SetOrientation(double x, double y, double z);
  void SetOrigin(double x, double y, double z);
  //@}

  //@{
  /// Particle radius [world units]; 0: automatic (0.6 x the field-data particle_spacing, else
  /// 0.6 x the mean spacing the bounds and the count imply).
  void SetParticleRadius(double radius);
  /// Point array of per-particle radii [world units]; empty: one radius for all.
  void SetRadiusArray(const char* name);
  /// The radius drawn last (after the automatic choice).
  double GetEffectiveParticleRadius() const;
  //@}

  //@{
  /// Forwarded to vtkPFScreenSpaceFluidMapper (see it for meanings and units).
  void SetSmoothingMethod(int method);
  void SetSmoothingIterations(int iterations);
  void SetFilterSize(double size);
  void SetMaxFilterRadius(int pixels);
  void SetDepthRange(double radii);
  void SetCurvatureFlowStep(double step);
  void SetDisplayMode(int mode);
  void SetFluidColor(double r, double g, double b);
  void SetAttenuationDistance(double distance);
  void SetRefractiveIndex(double index);
  void SetRefractionStrength(double strength);
  void SetShininess(double shininess);
  void SetSpecularStrength(double strength);
  void SetAmbient(double ambient);
  void SetColorMix(double mix);
  /// Six cube map faces (+X, -X, +Y, -Y, +Z, -Z; +Y of the images is world +Z), all or none.
  void SetEnvironmentImage(int face, const char* file);
  //@}

  vtkPFScreenSpaceFluidMapper* GetMapper() const;

protected:
  vtkPFScreenSpaceFluidRepresentation();
  ~vtkPFScreenSpaceFluidRepresentation() override;

  /// Draws with `mapper` instead (a style's mapper, Representations/NPR); call from the
  /// constructor of a derived representation, before any setting.
  void UseMapper(vtkPFScreenSpaceFluidMapper* mapper);

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkPFScreenSpaceFluidRepresentation(const vtkPFScreenSpaceFluidRepresentation&) = delete;
  void operator=(const vtkPFScreenSpaceFluidRepresentation&) = delete;

  void UpdateColoring();
  void UpdateRadius(vtkPolyData* particles);
  void UpdateEnvironment();

  vtkSmartPointer<vtkPFScreenSpaceFluidMapper> Mapper;
  vtkSmartPointer<vtkPFScreenSpaceFluidActor> Actor;
  vtkSmartPointer<vtkPolyData> Particles;
  double ParticleRadius = 0.0;
  std::string EnvironmentImages[6];
  bool EnvironmentChanged = false;
  // The session's processes (null in a serial one): the particles are drawn on process 0.
  std::unique_ptr<parafluid::Communicator> Processes;
  bool ProcessesAsked = false;
};
