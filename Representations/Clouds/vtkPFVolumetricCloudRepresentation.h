/**
 * @class vtkPFVolumetricCloudRepresentation
 * @brief ParaView's "Volumetric Cloud" representation: a 3-D image's scalar drawn as a cloud or
 * smoke by a vtkPFVolumetricCloudMapper through a vtkVolume, whose settings it forwards.
 *
 * Delivers the input image to the rendering process (one process: under MPI the image is
 * gathered, not composited piece by piece).
 */
#pragma once

#include "ParaFluidCloudsRepresentationsModule.h"
#include "vtkPVDataRepresentation.h"
#include "vtkSmartPointer.h"

class vtkImageData;
class vtkPFVolumetricCloudMapper;
class vtkVolume;

class PARAFLUIDCLOUDSREPRESENTATIONS_EXPORT vtkPFVolumetricCloudRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkPFVolumetricCloudRepresentation* New();
  vtkTypeMacro(vtkPFVolumetricCloudRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;
  void SetVisibility(bool visible) override;

  //@{
  void SetDensityArray(const char* name);
  void SetExtinction(double value);
  void SetAlbedo(double value);
  void SetAnisotropy(double value);
  void SetStepSize(double samples);
  void SetMaxSteps(int steps);
  void SetMinTransmittance(double value);
  void SetShadows(bool on);
  void SetOctaves(int octaves);
  void SetPowder(double value);
  void SetEmptySpaceSkipping(bool on);
  void SetLightMode(int mode);
  void SetSunElevation(double degrees);
  void SetSunAzimuth(double degrees);
  void SetSunColor(double r, double g, double b);
  void SetLightIntensity(double value);
  void SetSkyColor(double r, double g, double b);
  void SetDisplayMode(int mode);
  //@}

  vtkPFVolumetricCloudMapper* GetMapper() const;

protected:
  vtkPFVolumetricCloudRepresentation();
  ~vtkPFVolumetricCloudRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkPFVolumetricCloudRepresentation(const vtkPFVolumetricCloudRepresentation&) = delete;
  void operator=(const vtkPFVolumetricCloudRepresentation&) = delete;

  vtkSmartPointer<vtkPFVolumetricCloudMapper> Mapper;
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkImageData> Image;
};
