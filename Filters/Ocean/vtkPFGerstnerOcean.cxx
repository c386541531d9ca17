#include "vtkPFGerstnerOcean.h"

#include "GuardedRequest.h"
#include "LongWork.h"
#include "OutputTimes.h"
#include "ParameterCheck.h"
#include "parafluid/common/MemoryBudget.h"

#include "ParticleContract.h"

#include "HeightFieldFromData.h"

#include "parafluid/ocean/Bathymetry.h"
#include "parafluid/ocean/GerstnerOcean.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

vtkStandardNewMacro(vtkPFGerstnerOcean);

vtkPFGerstnerOcean::vtkPFGerstnerOcean()
{
  // The bathymetry comes on port 1; port 0 is never connected. pvpython's simple module gives a new
  // proxy the active source as its port-0 input, which would silently turn whatever was selected
  // into a sea floor.
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

void vtkPFGerstnerOcean::SetWave(int index, double amplitude, double wavelength, double direction, double steepness,
                                 double phase)
{
  const double values[5] = { amplitude, wavelength, direction, steepness, phase };
  if (this->Sea.setWave(index, values))
  {
    this->Modified();
  }
}

void vtkPFGerstnerOcean::RemoveAllWaves()
{
  if (!this->Sea.waves.empty())
  {
    this->Sea.waves.clear();
    this->Modified();
  }
}

void vtkPFGerstnerOcean::SetBathymetryConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

int vtkPFGerstnerOcean::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  }
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

namespace
{
/// Time steps offered at most: beyond it the GUI's time list itself becomes the slow part.
constexpr double kMaxFrames = 100000.0;
} // namespace

int vtkPFGerstnerOcean::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  parafluid::vtk::ParameterCheck check;
  check.inRange("Duration", this->Duration, 0.0, 1e6, "s")
    .inRange("FrameRate", this->FrameRate, 1e-3, 1e4, "frames per second")
    .require(this->Duration * this->FrameRate <= kMaxFrames,
             "Duration x FrameRate = " + parafluid::vtk::ParameterCheck::number(this->Duration * this->FrameRate) +
               " frames, more than " + std::to_string(static_cast<int>(kMaxFrames)) + ": lower Duration or FrameRate");
  if (!check.ok())
  {
    vtkErrorMacro("Gerstner Ocean: " << check.problem());
    return 0;
  }
  const double duration = this->Duration;
  const double rate = this->FrameRate;
  const auto frames = static_cast<int>(std::floor(duration * rate + 1e-9));
  std::vector<double> times;
  for (int k = 0; k <= frames; ++k)
  {
    times.push_back(k / rate);
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { 0.0, times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkPFGerstnerOcean::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, "Gerstner Ocean",
    [&]() -> int
    {
      using namespace parafluid::ocean;
      vtkInformation* outInfo = outputVector->GetInformationObject(0);
      vtkPolyData* output = vtkPolyData::GetData(outInfo);
      const double requested = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                                 ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                                 : 0.0;
      if (std::isnan(requested))
      {
        vtkErrorMacro(<< parafluid::vtk::notATimeError("Gerstner Ocean"));
        return 0;
      }
      // Any time in the offered range as asked; past its end the last frame, before it the first.
      const double last =
        this->FrameRate > 0.0 ? std::floor(this->Duration * this->FrameRate + 1e-9) / this->FrameRate : 0.0;
      const double time = std::clamp(requested, 0.0, std::isfinite(last) ? last : 0.0);
      const int nx = this->Resolution[0], ny = this->Resolution[1];
      parafluid::vtk::ParameterCheck check;
      check.inRange("Resolution", nx, 2, 65536)
        .inRange("Resolution", ny, 2, 65536)
        .allInRange("Size", this->Size, 2, 1e-6, 1e7, "m")
        .allInRange("Origin", this->Origin, 2, -1e7, 1e7, "m")
        .require(this->Sea.validate().empty(), this->Sea.validate());
      // About 60 bytes a vertex: points, normals, two triangles' connectivity, foam and wave arrays.
      const std::string memory = parafluid::checkMemoryBudget(
        60.0 * nx * ny, "a sea of Resolution " + std::to_string(nx) + " x " + std::to_string(ny));
      check.require(memory.empty(), memory);
      if (!check.ok())
      {
        vtkErrorMacro("Gerstner Ocean: " << check.problem());
        return 0;
      }
      if (static_cast<double>(nx) * ny > 4.0e6)
      {
        vtkWarningMacro("Gerstner Ocean: Resolution " << nx << " x " << ny << " is "
                                                      << static_cast<double>(nx) * ny / 1e6
                                                      << " million vertices per frame: expect a slow update");
      }

      const OceanParameters p = this->Sea.parameters();
      if (this->Sea.seaState == CUSTOM && p.waves.empty())
      {
        vtkWarningMacro("Sea State is Custom but the wave list is empty: the sea is flat");
      }

      std::shared_ptr<Bathymetry> floor;
      vtkDataObject* floorData =
        this->GetNumberOfInputConnections(1) > 0 ? vtkDataObject::GetData(inputVector[1], 0) : nullptr;
      if (floorData)
      {
        std::string error;
        floor = parafluid::vtk::heightFieldFrom(floorData, this->Sea.seaLevel, this->Sea.bathymetryResolution, error);
        if (!floor)
        {
          vtkErrorMacro("Bathymetry: " << error);
          return 0;
        }
      }
      const double region[4] = { this->Origin[0], this->Origin[0] + this->Size[0], this->Origin[1],
                                 this->Origin[1] + this->Size[1] };
      std::unique_ptr<GerstnerOcean> ocean;
      try
      {
        ocean = std::make_unique<GerstnerOcean>(p, floor, region);
      }
      catch (const std::exception& e)
      {
        vtkErrorMacro(<< parafluid::vtk::exceptionText(e));
        return 0;
      }

      // Rest points, row by row; evaluated a block of rows at a time for progress and abort.
      const vtkIdType n = static_cast<vtkIdType>(nx) * ny;
      std::vector<float> xs(static_cast<std::size_t>(n)), ys(static_cast<std::size_t>(n));
      for (int j = 0; j < ny; ++j)
      {
        for (int i = 0; i < nx; ++i)
        {
          const std::size_t k = static_cast<std::size_t>(j) * nx + i;
          xs[k] = static_cast<float>(region[0] + this->Size[0] * i / (nx - 1));
          ys[k] = static_cast<float>(region[2] + this->Size[1] * j / (ny - 1));
        }
      }
      vtkNew<vtkFloatArray> displacement, normals, jacobian, foam, depth;
      displacement->SetNumberOfComponents(3);
      displacement->SetNumberOfTuples(n);
      normals->SetName("Normals");
      normals->SetNumberOfComponents(3);
      normals->SetNumberOfTuples(n);
      jacobian->SetName("jacobian");
      jacobian->SetNumberOfTuples(n);
      foam->SetName("foam");
      foam->SetNumberOfTuples(n);
      depth->SetName("depth");
      depth->SetNumberOfTuples(n);
      const bool hasBottom = floor || this->Sea.waterDepth > 0.0;
      // Blocks of at most 2^19 vertices (0.15 s each here), so progress and Abort keep up.
      const int blocks = static_cast<int>(std::min<std::size_t>(
        static_cast<std::size_t>(ny), std::max<std::size_t>(32, static_cast<std::size_t>(n >> 19) + 1)));
      // Nominal cost on a 2-core machine: 0.29 us a vertex (the default sea state).
      parafluid::vtk::LongWork work(this, "Gerstner Ocean",
                                    { static_cast<double>(n), 2.9e-7, "vertices", "Resolution" });
      for (int b = 0; b < blocks; ++b)
      {
        const std::size_t first = static_cast<std::size_t>(ny) * b / blocks * nx;
        const std::size_t last = static_cast<std::size_t>(ny) * (b + 1) / blocks * nx;
        ocean->evaluate(xs.data() + first, ys.data() + first, last - first, time, displacement->GetPointer(3 * first),
                        normals->GetPointer(3 * first), jacobian->GetPointer(first), foam->GetPointer(first),
                        depth->GetPointer(first));
        if (!work.advance(static_cast<double>(last)))
        {
          return 1;
        }
      }

      vtkNew<vtkPoints> points;
      points->SetDataTypeToFloat();
      points->SetNumberOfPoints(n);
      float* xyz = static_cast<float*>(points->GetVoidPointer(0));
      const float* d = displacement->GetPointer(0);
      const auto level = static_cast<float>(this->Sea.seaLevel);
      for (vtkIdType k = 0; k < n; ++k)
      {
        xyz[3 * k] = xs[static_cast<std::size_t>(k)] + d[3 * k];
        xyz[3 * k + 1] = ys[static_cast<std::size_t>(k)] + d[3 * k + 1];
        xyz[3 * k + 2] = level + d[3 * k + 2];
      }
      // Quads in one offsets/connectivity pair (no per-cell insertion).
      const vtkIdType quads = static_cast<vtkIdType>(nx - 1) * (ny - 1);
      vtkNew<vtkIdTypeArray> offsets, connectivity;
      offsets->SetNumberOfTuples(quads + 1);
      connectivity->SetNumberOfTuples(4 * quads);
      vtkIdType* o = offsets->GetPointer(0);
      vtkIdType* c = connectivity->GetPointer(0);
      vtkIdType q = 0;
      for (int j = 0; j + 1 < ny; ++j)
      {
        for (int i = 0; i + 1 < nx; ++i, ++q)
        {
          const vtkIdType a = static_cast<vtkIdType>(j) * nx + i;
          o[q] = 4 * q;
          c[4 * q] = a;
          c[4 * q + 1] = a + 1;
          c[4 * q + 2] = a + 1 + nx;
          c[4 * q + 3] = a + nx;
        }
      }
      o[quads] = 4 * quads;
      vtkNew<vtkCellArray> cells;
      cells->SetData(offsets, connectivity);
      output->SetPoints(points);
      output->SetPolys(cells);
      output->GetPointData()->SetNormals(normals);
      output->GetPointData()->AddArray(jacobian);
      output->GetPointData()->AddArray(foam);
      if (hasBottom)
      {
        output->GetPointData()->AddArray(depth);
      }
      vtkNew<vtkDoubleArray> timeArray;
      timeArray->SetName(parafluid::contract::Time);
      timeArray->InsertNextValue(time);
      output->GetFieldData()->AddArray(timeArray);
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
      return 1;
    });
}

void vtkPFGerstnerOcean::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: " << this->Origin[0] << ", " << this->Origin[1] << "\n";
  os << indent << "Size: " << this->Size[0] << ", " << this->Size[1] << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
  os << indent << "SeaState: " << this->Sea.seaState << ", waves in list: " << this->GetNumberOfWaves() << "\n";
  os << indent << "WaterDepth: " << this->Sea.waterDepth << "\n";
}
