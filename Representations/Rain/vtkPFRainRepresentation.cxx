#include "vtkPFRainRepresentation.h"

#include "FluidParticleGather.h"
#include "ParticleArrays.h"
#include "ProcessCommunicator.h"
#include "parafluid/common/Communicator.h"
#include "vtkPFRainMapper.h"
#include "vtkPFScreenSpaceFluidActor.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkPFRainRepresentation);

vtkPFRainRepresentation::vtkPFRainRepresentation()
  : Mapper(vtkSmartPointer<vtkPFRainMapper>::New())
  , Actor(vtkSmartPointer<vtkPFScreenSpaceFluidActor>::New())
  , Points(vtkSmartPointer<vtkPolyData>::New())
{
  this->Actor->SetMapper(this->Mapper);
}

vtkPFRainRepresentation::~vtkPFRainRepresentation() = default;

void vtkPFRainRepresentation::SetKind(int kind)
{
  this->Mapper->SetKind(kind);
}
void vtkPFRainRepresentation::SetDisplayMode(int mode)
{
  this->Mapper->SetDisplayMode(mode);
}
void vtkPFRainRepresentation::SetRefractiveIndex(double index)
{
  this->Mapper->SetRefractiveIndex(index);
}
void vtkPFRainRepresentation::SetBrightness(double brightness)
{
  this->Mapper->SetBrightness(brightness);
}
void vtkPFRainRepresentation::SetOpacity(double opacity)
{
  this->Mapper->SetOpacity(opacity);
}
void vtkPFRainRepresentation::SetFogDistance(double distance)
{
  this->Mapper->SetFogDistance(distance);
}
void vtkPFRainRepresentation::SetWidthScale(double scale)
{
  this->Mapper->SetWidthScale(scale);
}
void vtkPFRainRepresentation::SetRasteriser(int rasteriser)
{
  this->Mapper->SetRasteriser(rasteriser);
}
int vtkPFRainRepresentation::GetLastDrawnOnCpu()
{
  return this->Mapper->GetLastDrawnOnCpu() ? 1 : 0;
}
void vtkPFRainRepresentation::SetSplashSize(double size)
{
  this->Mapper->SetSplashSize(size);
}
void vtkPFRainRepresentation::SetSplashLifetime(double lifetime)
{
  this->Mapper->SetSplashLifetime(lifetime);
}
void vtkPFRainRepresentation::SetEnvironmentImage(int face, const char* file)
{
  this->Mapper->SetEnvironmentImage(face, file);
}

int vtkPFRainRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPFRainRepresentation::RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                                         vtkInformationVector* outputVector)
{
  this->Points = vtkSmartPointer<vtkPolyData>::New();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataSet* data = vtkDataSet::SafeDownCast(input);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    // The first non-empty block (the Rain filter gives plain polydata).
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal() && !data; it->GoToNextItem())
    {
      auto* block = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      data = block && block->GetNumberOfPoints() > 0 ? block : nullptr;
    }
  }
  if (data && data->GetNumberOfPoints() > 0)
  {
    if (auto* pointSet = vtkPointSet::SafeDownCast(data))
    {
      this->Points->SetPoints(pointSet->GetPoints());
    }
    else
    {
      vtkNew<vtkPoints> points;
      points->SetNumberOfPoints(data->GetNumberOfPoints());
      for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
      {
        points->SetPoint(i, data->GetPoint(i));
      }
      this->Points->SetPoints(points);
    }
    this->Points->GetPointData()->ShallowCopy(data->GetPointData());
  }
  if (!this->ProcessesAsked)
  {
    // Collective, and every process's representation reaches its first RequestData together.
    this->Processes = parafluid::vtk::makeProcessCommunicator();
    this->ProcessesAsked = true;
  }
  if (this->Processes)
  {
    this->Points = parafluid::gatherParticlesOnFirst(this->Points, *this->Processes);
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkPFRainRepresentation::ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
                                                vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVRenderView::SetPiece(inInfo, this, this->Points);
    if (this->Processes)
    {
      // A shared render runs collectives in the mapper: IceT must render every process.
      outInfo->Set(vtkPVRenderView::RENDER_EMPTY_IMAGES(), 1);
    }
    if (this->Points->GetNumberOfPoints() > 0)
    {
      double bounds[6];
      this->Points->GetBounds(bounds);
      vtkNew<vtkMatrix4x4> identity;
      vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, identity);
    }
  }
  else if (request == vtkPVView::REQUEST_RENDER())
  {
    vtkPolyData* delivered = nullptr;
    if (vtkAlgorithmOutput* port = vtkPVRenderView::GetPieceProducer(inInfo, this, 0))
    {
      delivered = parafluid::vtk::firstPolyData(port->GetProducer()->GetOutputDataObject(port->GetIndex()));
    }
    this->Mapper->SetInputDataObject(delivered ? delivered : vtkSmartPointer<vtkPolyData>::New().Get());
    this->Mapper->SetSharedRendering(parafluid::sharedRenderingOf(inInfo, this->Processes.get()));
    if (auto* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW())))
    {
      // Read before the render begins, while the renderer still shows the view's background.
      vtkRenderer* renderer = view->GetRenderer();
      double bottom[3], top[3];
      renderer->GetBackground(bottom);
      renderer->GetBackground2(top);
      this->Mapper->SetViewBackground(bottom, renderer->GetGradientBackground() ? top : bottom);
    }
  }
  return 1;
}

bool vtkPFRainRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkPFRainRepresentation::RemoveFromView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkPFRainRepresentation::SetVisibility(bool visible)
{
  this->Actor->SetVisibility(visible);
  this->Superclass::SetVisibility(visible);
}
