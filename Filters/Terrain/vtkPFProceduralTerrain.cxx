#include "vtkPFProceduralTerrain.h"

#include "ParameterCheck.h"
#include "parafluid/common/MemoryBudget.h"
#include "parafluid/terrain/TerrainParameterTables.h"

#include "vtkObjectFactory.h"

#include <exception>

vtkStandardNewMacro(vtkPFProceduralTerrain);

vtkPFProceduralTerrain::vtkPFProceduralTerrain()
{
  this->SetNumberOfInputPorts(0);
  this->Settings = parafluid::terrain::proceduralTerrainDefaults();
}

bool vtkPFProceduralTerrain::TerrainGeometry(vtkInformationVector**, int dims[2], double origin[2], double spacing[2])
{
  if (this->Resolution[0] < 2 || this->Resolution[1] < 2 || !(this->Extent[0] > 0.0 && this->Extent[1] > 0.0))
  {
    return false;
  }
  for (int a = 0; a < 2; ++a)
  {
    dims[a] = this->Resolution[a];
    origin[a] = this->Origin[a];
    spacing[a] = this->Extent[a] / (this->Resolution[a] - 1);
  }
  return true;
}

bool vtkPFProceduralTerrain::ComputeTerrain(vtkInformationVector**, parafluid::terrain::ElevationGrid& grid,
                                            NamedArrays&)
{
  parafluid::vtk::ParameterCheck check;
  check.inRange("Resolution", this->Resolution[0], 2, 32769)
    .inRange("Resolution", this->Resolution[1], 2, 32769)
    .allInRange("Extent", this->Extent, 2, 1e-6, 1e9, "m")
    .allInRange("Origin", this->Origin, 2, -1e9, 1e9, "m");
  // About 40 bytes a sample: the elevation, the surface's points, normals and triangles.
  const std::string memory = parafluid::checkMemoryBudget(
    40.0 * this->Resolution[0] * this->Resolution[1],
    "a terrain of Resolution " + std::to_string(this->Resolution[0]) + " x " + std::to_string(this->Resolution[1]));
  check.require(memory.empty(), memory).require(this->Settings.problem().empty(), this->Settings.problem());
  if (!check.ok())
  {
    vtkErrorMacro("Procedural Terrain: " << check.problem());
    return false;
  }
  double origin[2], spacing[2];
  int dims[2];
  this->TerrainGeometry(nullptr, dims, origin, spacing);
  grid.nx = dims[0], grid.ny = dims[1];
  grid.x0 = origin[0], grid.y0 = origin[1];
  grid.dx = spacing[0], grid.dy = spacing[1];
  if (!parafluid::terrain::generateTerrain(this->Settings, grid, [this](double f) { return this->Progress(f); }))
  {
    vtkWarningMacro("Procedural Terrain: stopped by the user");
    return false;
  }
  return true;
}
