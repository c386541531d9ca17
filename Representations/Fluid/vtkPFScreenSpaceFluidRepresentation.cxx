#include "vtkPFScreenSpaceFluidRepresentation.h"

#include "FluidParticleGather.h"
#include "ParticleArrays.h"
#include "ProcessCommunicator.h"
#include "parafluid/common/Communicator.h"
#include "vtkPFScreenSpaceFluidActor.h"
#include "vtkPFScreenSpaceFluidMapper.h"

#include "vtkAlgorithmOutput.h"
#include "vtkAppendPolyData.h"
#include "vtkCellTypes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
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
#include "vtkScalarsToColors.h"
#include "vtkTexture.h"

#include <cmath>

vtkStandardNewMacro(vtkPFScreenSpaceFluidRepresentation);

namespace
{
/// The points of one dataset as particles: a polydata with its points and point arrays, no cells.
/// Sets `hadCells` when the dataset had cells other than vertices (they are not drawn).
vtkSmartPointer<vtkPolyData> particlesOf(vtkDataSet* data, bool& hadCells)
{
  auto particles = vtkSmartPointer<vtkPolyData>::New();
  if (!data || data->GetNumberOfPoints() == 0)
  {
    return particles;
  }
  if (auto* pointSet = vtkPointSet::SafeDownCast(data))
  {
    particles->SetPoints(pointSet->GetPoints());
  }
  else
  {
    vtkNew<vtkPoints> points;
    points->SetNumberOfPoints(data->GetNumberOfPoints());
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      points->SetPoint(i, data->GetPoint(i));
    }
    particles->SetPoints(points);
  }
  particles->GetPointData()->ShallowCopy(data->GetPointData());
  particles->GetFieldData()->ShallowCopy(data->GetFieldData());
  if (data->GetNumberOfCells() > 0)
  {
    vtkNew<vtkCellTypes> types;
    data->GetCellTypes(types);
    for (vtkIdType i = 0; i < types->GetNumberOfTypes(); ++i)
    {
      hadCells = hadCells || (types->GetCellType(i) != VTK_VERTEX && types->GetCellType(i) != VTK_POLY_VERTEX);
    }
  }
  return particles;
}
}

vtkPFScreenSpaceFluidRepresentation::vtkPFScreenSpaceFluidRepresentation()
  : Mapper(vtkSmartPointer<vtkPFScreenSpaceFluidMapper>::New())
  , Actor(vtkSmartPointer<vtkPFScreenSpaceFluidActor>::New())
  , Particles(vtkSmartPointer<vtkPolyData>::New())
{
  this->UseMapper(this->Mapper);
}

vtkPFScreenSpaceFluidRepresentation::~vtkPFScreenSpaceFluidRepresentation() = default;

void vtkPFScreenSpaceFluidRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParticleRadius: " << this->ParticleRadius << "\n";
}

void vtkPFScreenSpaceFluidRepresentation::UseMapper(vtkPFScreenSpaceFluidMapper* mapper)
{
  this->Mapper = mapper;
  this->Actor->SetMapper(this->Mapper);
  this->Mapper->SetScalarVisibility(0);
  this->Mapper->SetColorModeToMapScalars();
}

vtkPFScreenSpaceFluidMapper* vtkPFScreenSpaceFluidRepresentation::GetMapper() const
{
  return this->Mapper;
}

int vtkPFScreenSpaceFluidRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  // Representations have no input on the client in client-server mode.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPFScreenSpaceFluidRepresentation::RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                                                     vtkInformationVector* outputVector)
{
  this->Particles = vtkSmartPointer<vtkPolyData>::New();
  bool hadCells = false;
  if (vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0))
  {
    if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
    {
      vtkNew<vtkAppendPolyData> append;
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(composite->NewIterator());
      vtkFieldData* fieldData = nullptr;
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        auto* block = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
        if (block && block->GetNumberOfPoints() > 0)
        {
          append->AddInputData(particlesOf(block, hadCells));
          fieldData = fieldData ? fieldData : block->GetFieldData();
        }
      }
      if (append->GetNumberOfInputConnections(0) > 0)
      {
        append->Update();
        this->Particles->ShallowCopy(append->GetOutput());
        if (fieldData)
        {
          this->Particles->GetFieldData()->ShallowCopy(fieldData);
        }
      }
    }
    else
    {
      this->Particles = particlesOf(vtkDataSet::SafeDownCast(input), hadCells);
    }
  }
  if (!this->ProcessesAsked)
  {
    // Collective, and every process's representation reaches its first RequestData together.
    this->Processes = parafluid::vtk::makeProcessCommunicator();
    this->ProcessesAsked = true;
  }
  if (this->Processes)
  {
    this->Particles = parafluid::gatherParticlesOnFirst(this->Particles, *this->Processes);
  }
  if (hadCells)
  {
    vtkWarningMacro("Screen-Space Fluid draws the points of its input as particles; the input's cells "
                    "(other than vertices) are not drawn.");
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkPFScreenSpaceFluidRepresentation::ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
                                                            vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVRenderView::SetPiece(inInfo, this, this->Particles);
    if (this->Processes)
    {
      // A shared render runs collectives in the mapper: IceT must render every process.
      outInfo->Set(vtkPVRenderView::RENDER_EMPTY_IMAGES(), 1);
    }
    double bounds[6];
    this->Particles->GetBounds(bounds);
    if (this->Particles->GetNumberOfPoints() > 0)
    {
      // The spheres reach past the centres; a generous margin keeps them inside the clipping range.
      // The radius is brought up to date first: the bounds used to lag one update behind a change
      // of ParticleRadius (a radius made small again kept the huge clipping range of the large one).
      this->UpdateRadius(this->Particles);
      const double grow = 2.0 * this->GetEffectiveParticleRadius();
      for (int i = 0; i < 3; ++i)
      {
        bounds[2 * i] -= grow;
        bounds[2 * i + 1] += grow;
      }
      vtkNew<vtkMatrix4x4> matrix;
      this->Actor->GetMatrix(matrix);
      vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, matrix);
    }
  }
  else if (request == vtkPVView::REQUEST_RENDER())
  {
    const parafluid::SharedRendering sharing = parafluid::sharedRenderingOf(inInfo, this->Processes.get());
    this->Mapper->SetSharedRendering(sharing);
    vtkPolyData* delivered = nullptr;
    if (vtkAlgorithmOutput* port = vtkPVRenderView::GetPieceProducer(inInfo, this, 0))
    {
      delivered = parafluid::vtk::firstPolyData(port->GetProducer()->GetOutputDataObject(port->GetIndex()));
    }
    if (delivered)
    {
      this->Mapper->SetInputDataObject(delivered);
    }
    else
    {
      this->Mapper->SetInputDataObject(vtkSmartPointer<vtkPolyData>::New());
    }
    this->UpdateRadius(delivered);
    this->UpdateColoring();
    this->UpdateEnvironment();
  }
  return 1;
}

bool vtkPFScreenSpaceFluidRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkPFScreenSpaceFluidRepresentation::RemoveFromView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkPFScreenSpaceFluidRepresentation::SetVisibility(bool visible)
{
  this->Actor->SetVisibility(visible);
  this->Superclass::SetVisibility(visible);
}

void vtkPFScreenSpaceFluidRepresentation::UpdateColoring()
{
  vtkInformation* info = this->GetInputArrayInformation(0);
  const char* name = info && info->Has(vtkDataObject::FIELD_NAME()) ? info->Get(vtkDataObject::FIELD_NAME()) : nullptr;
  const int association = info && info->Has(vtkDataObject::FIELD_ASSOCIATION())
                            ? info->Get(vtkDataObject::FIELD_ASSOCIATION())
                            : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (name && name[0] && association == vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    this->Mapper->SetScalarVisibility(1);
    this->Mapper->SetScalarModeToUsePointFieldData();
    this->Mapper->SelectColorArray(name);
    this->Mapper->SetUseLookupTableScalarRange(1);
  }
  else
  {
    // Particles carry no cells: cell colouring has nothing to colour.
    this->Mapper->SetScalarVisibility(0);
  }
}

void vtkPFScreenSpaceFluidRepresentation::UpdateRadius(vtkPolyData* particles)
{
  double radius = this->ParticleRadius;
  if (radius <= 0.0)
  {
    radius = 1.0;
    if (particles && particles->GetNumberOfPoints() > 0)
    {
      const double spacing =
        parafluid::vtk::fieldValue(particles->GetFieldData(), parafluid::contract::ParticleSpacing, 0.0);
      if (spacing > 0.0)
      {
        radius = 0.6 * spacing;
      }
      else
      {
        // Mean spacing of the points spread evenly through their bounding box's non-flat axes.
        double b[6];
        particles->GetBounds(b);
        double volume = 1.0;
        int axes = 0;
        for (int i = 0; i < 3; ++i)
        {
          if (b[2 * i + 1] - b[2 * i] > 0.0)
          {
            volume *= b[2 * i + 1] - b[2 * i];
            ++axes;
          }
        }
        if (axes > 0)
        {
          radius = 0.6 * std::pow(volume / static_cast<double>(particles->GetNumberOfPoints()), 1.0 / axes);
        }
      }
    }
  }
  this->Mapper->SetParticleRadius(radius);
}

double vtkPFScreenSpaceFluidRepresentation::GetEffectiveParticleRadius() const
{
  return this->Mapper->GetParticleRadius();
}

void vtkPFScreenSpaceFluidRepresentation::UpdateEnvironment()
{
  if (!this->EnvironmentChanged)
  {
    return;
  }
  this->EnvironmentChanged = false;
  int given = 0;
  for (const auto& file : this->EnvironmentImages)
  {
    given += file.empty() ? 0 : 1;
  }
  if (given == 0)
  {
    this->Mapper->SetEnvironmentTexture(nullptr);
    return;
  }
  if (given != 6)
  {
    vtkErrorMacro("Screen-Space Fluid needs all six environment images (+X, -X, +Y, -Y, +Z, -Z); got "
                  << given << ". Reflecting the background instead.");
    this->Mapper->SetEnvironmentTexture(nullptr);
    return;
  }
  vtkNew<vtkTexture> cube;
  cube->CubeMapOn();
  cube->InterpolateOn();
  vtkNew<vtkImageReader2Factory> factory;
  for (int face = 0; face < 6; ++face)
  {
    vtkSmartPointer<vtkImageReader2> reader;
    reader.TakeReference(factory->CreateImageReader2(this->EnvironmentImages[face].c_str()));
    if (!reader)
    {
      vtkErrorMacro("Cannot read environment image '" << this->EnvironmentImages[face]
                                                      << "' (missing, or not an image format VTK reads).");
      this->Mapper->SetEnvironmentTexture(nullptr);
      return;
    }
    reader->SetFileName(this->EnvironmentImages[face].c_str());
    reader->Update();
    vtkNew<vtkImageData> image;
    image->ShallowCopy(reader->GetOutput());
    cube->SetInputDataObject(face, image);
  }
  this->Mapper->SetEnvironmentTexture(cube);
}

void vtkPFScreenSpaceFluidRepresentation::SetEnvironmentImage(int face, const char* file)
{
  if (face < 0 || face > 5)
  {
    return;
  }
  const std::string value = file ? file : "";
  if (value != this->EnvironmentImages[face])
  {
    this->EnvironmentImages[face] = value;
    this->EnvironmentChanged = true;
    this->Modified();
  }
}

void vtkPFScreenSpaceFluidRepresentation::SetParticleRadius(double radius)
{
  if (!std::isfinite(radius))
  {
    vtkWarningMacro(<< "ParticleRadius = " << radius << " is ignored: it must be a finite number (0: automatic)");
    return;
  }
  if (radius != this->ParticleRadius)
  {
    this->ParticleRadius = radius;
    this->MarkModified(); // the geometry bounds grow with the radius
  }
}

void vtkPFScreenSpaceFluidRepresentation::SetLookupTable(vtkScalarsToColors* lut)
{
  this->Mapper->SetLookupTable(lut);
}

void vtkPFScreenSpaceFluidRepresentation::SetMapScalars(int map)
{
  this->Mapper->SetColorMode(map ? VTK_COLOR_MODE_MAP_SCALARS : VTK_COLOR_MODE_DIRECT_SCALARS);
}

void vtkPFScreenSpaceFluidRepresentation::SetPosition(double x, double y, double z)
{
  this->Actor->SetPosition(x, y, z);
}
void vtkPFScreenSpaceFluidRepresentation::SetScale(double x, double y, double z)
{
  this->Actor->SetScale(x, y, z);
}
void vtkPFScreenSpaceFluidRepresentation::SetOrientation(double x, double y, double z)
{
  this->Actor->SetOrientation(x, y, z);
}
void vtkPFScreenSpaceFluidRepresentation::SetOrigin(double x, double y, double z)
{
  this->Actor->SetOrigin(x, y, z);
}

void vtkPFScreenSpaceFluidRepresentation::SetRadiusArray(const char* name)
{
  this->Mapper->SetRadiusArray(name);
}
void vtkPFScreenSpaceFluidRepresentation::SetSmoothingMethod(int method)
{
  this->Mapper->SetSmoothingMethod(method);
}
void vtkPFScreenSpaceFluidRepresentation::SetSmoothingIterations(int iterations)
{
  this->Mapper->SetSmoothingIterations(iterations);
}
void vtkPFScreenSpaceFluidRepresentation::SetFilterSize(double size)
{
  this->Mapper->SetFilterSize(size);
}
void vtkPFScreenSpaceFluidRepresentation::SetMaxFilterRadius(int pixels)
{
  this->Mapper->SetMaxFilterRadius(pixels);
}
void vtkPFScreenSpaceFluidRepresentation::SetDepthRange(double radii)
{
  this->Mapper->SetDepthRange(radii);
}
void vtkPFScreenSpaceFluidRepresentation::SetCurvatureFlowStep(double step)
{
  this->Mapper->SetCurvatureFlowStep(step);
}
void vtkPFScreenSpaceFluidRepresentation::SetDisplayMode(int mode)
{
  this->Mapper->SetDisplayMode(mode);
}
void vtkPFScreenSpaceFluidRepresentation::SetFluidColor(double r, double g, double b)
{
  this->Mapper->SetFluidColor(r, g, b);
}
void vtkPFScreenSpaceFluidRepresentation::SetAttenuationDistance(double distance)
{
  this->Mapper->SetAttenuationDistance(distance);
}
void vtkPFScreenSpaceFluidRepresentation::SetRefractiveIndex(double index)
{
  this->Mapper->SetRefractiveIndex(index);
}
void vtkPFScreenSpaceFluidRepresentation::SetRefractionStrength(double strength)
{
  this->Mapper->SetRefractionStrength(strength);
}
void vtkPFScreenSpaceFluidRepresentation::SetShininess(double shininess)
{
  this->Mapper->SetShininess(shininess);
}
void vtkPFScreenSpaceFluidRepresentation::SetSpecularStrength(double strength)
{
  this->Mapper->SetSpecularStrength(strength);
}
void vtkPFScreenSpaceFluidRepresentation::SetAmbient(double ambient)
{
  this->Mapper->SetAmbient(ambient);
}
void vtkPFScreenSpaceFluidRepresentation::SetColorMix(double mix)
{
  this->Mapper->SetColorMix(mix);
}
