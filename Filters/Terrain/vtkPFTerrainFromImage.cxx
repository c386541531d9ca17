#include "vtkPFTerrainFromImage.h"

#include "HeightImage.h"
#include "ParameterCheck.h"

#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>

vtkStandardNewMacro(vtkPFTerrainFromImage);

vtkPFTerrainFromImage::vtkPFTerrainFromImage()
{
  this->SetNumberOfInputPorts(1);
  // Default: the input's `elevation`, else its active scalars, else its first array.
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, "");
}

int vtkPFTerrainFromImage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

namespace
{
std::string chosenArray(vtkAlgorithm* algorithm)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(0);
  const char* name = info && info->Has(vtkDataObject::FIELD_NAME()) ? info->Get(vtkDataObject::FIELD_NAME()) : nullptr;
  return name ? name : "";
}
} // namespace

bool vtkPFTerrainFromImage::TerrainGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2],
                                            double spacing[2])
{
  if (!InputGeometry(inputVector, dims, origin, spacing))
  {
    return false;
  }
  for (int a = 0; a < 2; ++a)
  {
    spacing[a] = this->Spacing[a] > 0.0 ? this->Spacing[a] : spacing[a];
  }
  return true;
}

bool vtkPFTerrainFromImage::ComputeTerrain(vtkInformationVector** inputVector, parafluid::terrain::ElevationGrid& grid,
                                           NamedArrays&)
{
  parafluid::vtk::ParameterCheck check;
  check.inRange("HeightScale", this->HeightScale, -1e6, 1e6)
    .inRange("BaseHeight", this->BaseHeight, -1e7, 1e7, "m")
    .allInRange("Spacing", this->Spacing, 2, 0.0, 1e7, "m");
  if (!check.ok())
  {
    vtkErrorMacro("Terrain From Image: " << check.problem());
    return false;
  }
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  parafluid::vtk::HeightImage heights;
  std::string error;
  if (!parafluid::vtk::readHeightImage(input, chosenArray(this), heights, error))
  {
    vtkErrorMacro("Terrain From Image: " << error);
    return false;
  }
  std::vector<unsigned char> valid(heights.heights.size(), 1);
  std::size_t missing = 0;
  for (std::size_t k = 0; k < heights.heights.size(); ++k)
  {
    const float v = heights.heights[k];
    if (!std::isfinite(v) ||
        (this->UseNoDataValue && static_cast<double>(v) == static_cast<double>(static_cast<float>(this->NoDataValue))))
    {
      valid[k] = 0, ++missing;
    }
  }
  this->FilledSamples = static_cast<long long>(missing);
  if (missing == heights.heights.size())
  {
    vtkErrorMacro("Terrain From Image: every sample of '"
                  << heights.arrayName << "' is no-data (NaN or NoDataValue): nothing to make a terrain of");
    return false;
  }
  if (missing > 0)
  {
    parafluid::terrain::fillNoData(heights.heights, heights.nx, heights.ny, valid);
  }
  grid.nx = heights.nx, grid.ny = heights.ny;
  grid.x0 = heights.origin[0], grid.y0 = heights.origin[1];
  grid.dx = this->Spacing[0] > 0.0 ? this->Spacing[0] : heights.spacing[0];
  grid.dy = this->Spacing[1] > 0.0 ? this->Spacing[1] : heights.spacing[1];
  grid.elevation.resize(heights.heights.size());
  for (std::size_t k = 0; k < heights.heights.size(); ++k)
  {
    grid.elevation[k] = static_cast<float>(this->HeightScale * heights.heights[k] + this->BaseHeight);
  }
  return true;
}
