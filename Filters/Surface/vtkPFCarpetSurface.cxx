#include "vtkPFCarpetSurface.h"

#include "GuardedRequest.h"
#include "HeightFieldFromData.h"
#include "ParticleArrays.h"
#include "SurfaceMeshOutput.h"
#include "parafluid/common/MemoryBudget.h"

#include "parafluid/common/HeightField.h"
#include "parafluid/surface/CarpetSurface.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkPFCarpetSurface);

vtkPFCarpetSurface::vtkPFCarpetSurface()
  : vtkPFParticleAlgorithm("Carpet Surface")
  , Carpet(new parafluid::surface::CarpetSurface)
{
  this->SetNumberOfInputPorts(2);
  this->SetNonFinitePolicy(NonFinite::Drop);
}

vtkPFCarpetSurface::~vtkPFCarpetSurface() = default;

int vtkPFCarpetSurface::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkPFCarpetSurface::RequestParticles(const Particles& particles, vtkInformationVector** inputVector,
                                         vtkInformation*, vtkPolyData* output)
{
  vtkDataObject* terrainData = inputVector[1]->GetNumberOfInformationObjects() > 0
                                 ? inputVector[1]->GetInformationObject(0)->Get(vtkDataObject::DATA_OBJECT())
                                 : nullptr;
  parafluid::vtk::ParameterCheck check;
  check.inRange("FallAcceleration", this->FallAcceleration, 0.0, 1e6, "m/s^2")
    .inRange("MinDepth", this->MinDepth, 0.0, 1e6, "m")
    .inRange("Resolution", this->Resolution, 1, 65536);
  // The ground raster, the terrain's raster and the carpet's copy: about 16 bytes a cell.
  const double cells = static_cast<double>(this->Resolution) * this->Resolution;
  const std::string memory =
    check.ok()
      ? parafluid::checkMemoryBudget(16.0 * cells, "a carpet of Resolution " + std::to_string(this->Resolution))
      : std::string();
  check.require(memory.empty(), memory + "; lower Resolution");
  if (!this->Accept(check))
  {
    return 0;
  }
  vtkPointSet* local = particles.Local;
  vtkPointSet* input = particles.Gathered;
  const vtkIdType n = input ? input->GetNumberOfPoints() : 0;
  const double time = local->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP())
                        ? local->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP())
                        : 0.0;

  // The state continues only forward in time, under unchanged properties and terrain.
  const vtkMTimeType settings = std::max(this->GetMTime(), terrainData ? terrainData->GetMTime() : 0);
  const bool continues = this->HasState && settings == this->StateTime && time >= this->LastTime;
  try
  {
    if (!continues)
    {
      const int r = this->Resolution;
      std::vector<float> ground(static_cast<std::size_t>(r) * r);
      double bounds[6] = { 0, 0, 0, 0, 0, 0 };
      if (terrainData)
      {
        std::string error;
        auto terrain = parafluid::vtk::heightFieldFrom(terrainData, 0.0, std::max(r, 64), error);
        if (!terrain)
        {
          this->ReportError("Terrain: " + error);
          return 0;
        }
        double b[4];
        terrain->bounds(b);
        std::copy(b, b + 4, bounds);
        for (int j = 0; j < r; ++j)
        {
          for (int i = 0; i < r; ++i)
          {
            const double x = b[0] + (i + 0.5) * (b[1] - b[0]) / r, y = b[2] + (j + 0.5) * (b[3] - b[2]) / r;
            ground[static_cast<std::size_t>(j) * r + i] = static_cast<float>(terrain->heightAt(x, y));
          }
        }
      }
      else
      {
        vtkDataArray* domain = vtkArrayDownCast<vtkDataArray>(
          local->GetFieldData() ? local->GetFieldData()->GetAbstractArray(parafluid::contract::DomainBounds) : nullptr);
        if (domain && domain->GetNumberOfValues() == 6)
        {
          for (int k = 0; k < 6; ++k)
          {
            bounds[k] = domain->GetComponent(k / domain->GetNumberOfComponents(), k % domain->GetNumberOfComponents());
          }
        }
        else if (n > 0)
        {
          input->GetBounds(bounds);
        }
        else
        {
          output->Initialize();
          return 1; // no particles and nothing to lay a grid on
        }
        std::fill(ground.begin(), ground.end(), static_cast<float>(bounds[4]));
      }
      if (!(bounds[1] > bounds[0]) || !(bounds[3] > bounds[2]))
      {
        this->ReportError("the domain has no extent in x or y (" + std::to_string(bounds[0]) + ".." +
                          std::to_string(bounds[1]) + ", " + std::to_string(bounds[2]) + ".." +
                          std::to_string(bounds[3]) + ")");
        return 0;
      }
      this->Carpet->setGrid(bounds[0], bounds[2], bounds[1], bounds[3], r, std::move(ground));
      this->LastTime = time;
    }
    std::vector<float> positionStorage;
    const float* xyz = n > 0 ? parafluid::vtk::positionsAsFloat(input, positionStorage) : nullptr;
    this->Carpet->advance(xyz, static_cast<std::size_t>(n), time - this->LastTime, this->FallAcceleration,
                          this->MinDepth);
    this->LastTime = time;
    this->StateTime = settings;
    this->HasState = true;
  }
  catch (const std::exception& e)
  {
    this->HasState = false;
    this->ReportError(parafluid::vtk::exceptionText(e));
    return 0;
  }
  std::vector<float> depth;
  std::size_t visited = 0;
  const parafluid::surface::SurfaceMesh mesh = this->Carpet->mesh(&depth, &visited);
  parafluid::vtk::meshToPolyData(mesh, output);
  output->GetPointData()->AddArray(parafluid::vtk::floatArray("depth", 1, depth));
  output->GetPointData()->SetActiveScalars("depth");
  this->WetCells = static_cast<vtkIdType>(this->Carpet->wetCells());
  this->VisitedNodes = static_cast<vtkIdType>(visited);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}

void vtkPFCarpetSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "FallAcceleration: " << this->FallAcceleration << "\n";
  os << indent << "MinDepth: " << this->MinDepth << "\n";
}
