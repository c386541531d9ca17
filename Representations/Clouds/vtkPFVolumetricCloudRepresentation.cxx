#include "vtkPFVolumetricCloudRepresentation.h"

#include "vtkPFVolumetricCloudMapper.h"

#include "vtkAlgorithmOutput.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

vtkStandardNewMacro(vtkPFVolumetricCloudRepresentation);

vtkPFVolumetricCloudRepresentation::vtkPFVolumetricCloudRepresentation()
  : Mapper(vtkSmartPointer<vtkPFVolumetricCloudMapper>::New())
  , Volume(vtkSmartPointer<vtkVolume>::New())
  , Image(vtkSmartPointer<vtkImageData>::New())
{
  this->Volume->SetMapper(this->Mapper);
}

vtkPFVolumetricCloudRepresentation::~vtkPFVolumetricCloudRepresentation() = default;

vtkPFVolumetricCloudMapper* vtkPFVolumetricCloudRepresentation::GetMapper() const
{
  return this->Mapper;
}

void vtkPFVolumetricCloudRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

int vtkPFVolumetricCloudRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  // Representations have no input on the client in client-server mode.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPFVolumetricCloudRepresentation::RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                                                    vtkInformationVector* outputVector)
{
  this->Image = vtkSmartPointer<vtkImageData>::New();
  if (auto* input = vtkImageData::GetData(inputVector[0], 0))
  {
    this->Image->ShallowCopy(input);
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkPFVolumetricCloudRepresentation::ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
                                                           vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVRenderView::SetPiece(inInfo, this, this->Image);
    if (this->Image->GetNumberOfPoints() > 0)
    {
      this->Mapper->SetInputData(this->Image);
      double bounds[6];
      std::copy(this->Mapper->GetBounds(), this->Mapper->GetBounds() + 6, bounds);
      vtkNew<vtkMatrix4x4> matrix;
      this->Volume->GetMatrix(matrix);
      vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, matrix);
    }
  }
  else if (request == vtkPVView::REQUEST_RENDER())
  {
    vtkImageData* delivered = nullptr;
    if (vtkAlgorithmOutput* port = vtkPVRenderView::GetPieceProducer(inInfo, this, 0))
    {
      delivered = vtkImageData::SafeDownCast(port->GetProducer()->GetOutputDataObject(port->GetIndex()));
    }
    this->Mapper->SetInputData(delivered ? delivered : vtkSmartPointer<vtkImageData>::New().Get());
  }
  return 1;
}

bool vtkPFVolumetricCloudRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->AddVolume(this->Volume);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkPFVolumetricCloudRepresentation::RemoveFromView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->RemoveVolume(this->Volume);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkPFVolumetricCloudRepresentation::SetVisibility(bool visible)
{
  this->Volume->SetVisibility(visible);
  this->Superclass::SetVisibility(visible);
}

void vtkPFVolumetricCloudRepresentation::SetDensityArray(const char* name)
{
  this->Mapper->SetDensityArray(name ? name : "");
}
void vtkPFVolumetricCloudRepresentation::SetExtinction(double value)
{
  this->Mapper->SetExtinction(value);
}
void vtkPFVolumetricCloudRepresentation::SetAlbedo(double value)
{
  this->Mapper->SetAlbedo(value);
}
void vtkPFVolumetricCloudRepresentation::SetAnisotropy(double value)
{
  this->Mapper->SetAnisotropy(value);
}
void vtkPFVolumetricCloudRepresentation::SetStepSize(double samples)
{
  this->Mapper->SetStepSize(samples);
}
void vtkPFVolumetricCloudRepresentation::SetMaxSteps(int steps)
{
  this->Mapper->SetMaxSteps(steps);
}
void vtkPFVolumetricCloudRepresentation::SetMinTransmittance(double value)
{
  this->Mapper->SetMinTransmittance(value);
}
void vtkPFVolumetricCloudRepresentation::SetShadows(bool on)
{
  this->Mapper->SetShadows(on);
}
void vtkPFVolumetricCloudRepresentation::SetOctaves(int octaves)
{
  this->Mapper->SetOctaves(octaves);
}
void vtkPFVolumetricCloudRepresentation::SetPowder(double value)
{
  this->Mapper->SetPowder(value);
}
void vtkPFVolumetricCloudRepresentation::SetEmptySpaceSkipping(bool on)
{
  this->Mapper->SetEmptySpaceSkipping(on);
}
void vtkPFVolumetricCloudRepresentation::SetLightMode(int mode)
{
  this->Mapper->SetLightMode(mode);
}
void vtkPFVolumetricCloudRepresentation::SetSunElevation(double degrees)
{
  this->Mapper->SetSunElevation(degrees);
}
void vtkPFVolumetricCloudRepresentation::SetSunAzimuth(double degrees)
{
  this->Mapper->SetSunAzimuth(degrees);
}
void vtkPFVolumetricCloudRepresentation::SetSunColor(double r, double g, double b)
{
  this->Mapper->SetSunColor(r, g, b);
}
void vtkPFVolumetricCloudRepresentation::SetLightIntensity(double value)
{
  this->Mapper->SetLightIntensity(value);
}
void vtkPFVolumetricCloudRepresentation::SetSkyColor(double r, double g, double b)
{
  this->Mapper->SetSkyColor(r, g, b);
}
void vtkPFVolumetricCloudRepresentation::SetDisplayMode(int mode)
{
  this->Mapper->SetDisplayMode(mode);
}
