#include "vtkPFTerrainAlgorithm.h"

#include "GuardedRequest.h"
#include "HeightImage.h"
#include "parafluid/terrain/TerrainShading.h"

#include "vtkDemandDrivenPipeline.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cstring>

vtkPFTerrainAlgorithm::vtkPFTerrainAlgorithm()
{
  this->SetNumberOfOutputPorts(2);
}

void vtkPFTerrainAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GenerateSurface: " << this->GenerateSurface << "\n";
  os << indent << "ComputeSlope: " << this->ComputeSlope << ", ComputeCurvature: " << this->ComputeCurvature << "\n";
}

int vtkPFTerrainAlgorithm::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

vtkTypeBool vtkPFTerrainAlgorithm::ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                                                  vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    return this->RequestInformation(inputVector, outputVector);
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    return this->RequestUpdateExtent(inputVector);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkPFTerrainAlgorithm::RequestInformation(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  int dims[2] = { 2, 2 };
  double origin[2] = { 0.0, 0.0 }, spacing[2] = { 1.0, 1.0 };
  // An unknown geometry (bad settings: RequestData reports why) still gives a valid extent.
  this->TerrainGeometry(inputVector, dims, origin, spacing);
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, dims[0] - 1, 0, dims[1] - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double o[3] = { origin[0], origin[1], 0.0 }, s[3] = { spacing[0], spacing[1], 1.0 };
  info->Set(vtkDataObject::ORIGIN(), o, 3);
  info->Set(vtkDataObject::SPACING(), s, 3);
  // The terrain is computed whole (erosion and fractals are not split into pieces).
  info->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 0);
  return 1;
}

int vtkPFTerrainAlgorithm::RequestUpdateExtent(vtkInformationVector** inputVector)
{
  for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      vtkInformation* in = inputVector[port]->GetInformationObject(c);
      if (in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      {
        in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
                in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
      in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    }
  }
  return 1;
}

bool vtkPFTerrainAlgorithm::InputGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2],
                                          double spacing[2])
{
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  if (!in || !in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return false;
  }
  int extent[6];
  in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double o[3] = { 0, 0, 0 }, s[3] = { 1, 1, 1 };
  if (in->Has(vtkDataObject::ORIGIN()))
  {
    in->Get(vtkDataObject::ORIGIN(), o);
  }
  if (in->Has(vtkDataObject::SPACING()))
  {
    in->Get(vtkDataObject::SPACING(), s);
  }
  // Point data is assumed here; an input with cell data (one fewer sample per side) is only
  // known in RequestData.
  for (int a = 0; a < 2; ++a)
  {
    dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    spacing[a] = s[a];
    origin[a] = o[a] + extent[2 * a] * s[a];
  }
  return true;
}

bool vtkPFTerrainAlgorithm::Progress(double fraction)
{
  this->UpdateProgress(fraction);
  return !this->CheckAbort();
}

namespace
{
vtkSmartPointer<vtkFloatArray> wrap(const char* name, std::vector<float>& values)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(float));
  return array;
}
} // namespace

int vtkPFTerrainAlgorithm::RequestData(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, this->Label(),
    [&]() -> int
    {
      vtkImageData* image = vtkImageData::GetData(outputVector, 0);
      vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
      parafluid::terrain::ElevationGrid grid;
      NamedArrays arrays;
      if (!this->ComputeTerrain(inputVector, grid, arrays))
      {
        return 0;
      }
      const std::string problem = grid.problem();
      if (!problem.empty())
      {
        vtkErrorMacro(<< this->Label() << ": " << problem);
        return 0;
      }
      if (this->ComputeSlope)
      {
        arrays.emplace_back("slope", parafluid::terrain::terrainSlope(grid));
      }
      if (this->ComputeCurvature)
      {
        arrays.emplace_back("curvature", parafluid::terrain::terrainCurvature(grid));
      }
      image->SetDimensions(grid.nx, grid.ny, 1);
      image->SetOrigin(grid.x0, grid.y0, 0.0);
      image->SetSpacing(grid.dx, grid.dy, 1.0);
      auto elevation = wrap(parafluid::vtk::kElevationArray, grid.elevation);
      image->GetPointData()->SetScalars(elevation);
      std::vector<vtkDataArray*> shared{ elevation };
      for (auto& [name, values] : arrays)
      {
        if (values.size() != grid.size())
        {
          continue;
        }
        auto array = wrap(name.c_str(), values);
        image->GetPointData()->AddArray(array);
        shared.push_back(array);
      }
      if (this->GenerateSurface)
      {
        const double origin[2] = { grid.x0, grid.y0 }, spacing[2] = { grid.dx, grid.dy };
        surface->ShallowCopy(parafluid::vtk::heightSurface(grid.elevation, grid.nx, grid.ny, origin, spacing, shared));
        surface->GetPointData()->SetActiveScalars(parafluid::vtk::kElevationArray);
      }
      return 1;
    });
}
