#include "vtkPFStableFluids.h"

#include "GuardedRequest.h"
#include "LongWork.h"
#include "OutputTimes.h"
#include "ParameterCheck.h"
#include "TimeSteppedCache.h"

#include "parafluid/clouds/CloudShapes.h"
#include "parafluid/clouds/GridSolvers.h"
#include "parafluid/clouds/StableFluids.h"
#include "parafluid/common/MemoryBudget.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

using parafluid::clouds::StableFluids;
using parafluid::clouds::StableFluidsParameters;
using parafluid::clouds::StaggeredGrid;

// What an output kept by the cache reports again when it is asked for a second time.
struct KeptCloudInfo
{
  long long steps = 0;
  int iterations = 0;
};

struct vtkPFStableFluids::Cache : parafluid::vtk::TimeSteppedCache<StableFluids, KeptCloudInfo>
{
  long long Steps = 0; // steps since the run started
};

vtkStandardNewMacro(vtkPFStableFluids);

vtkPFStableFluids::vtkPFStableFluids()
  : Cached(std::make_unique<Cache>())
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

vtkPFStableFluids::~vtkPFStableFluids() = default;

int vtkPFStableFluids::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

bool vtkPFStableFluids::GridShape(int cells[3], double& h)
{
  parafluid::vtk::ParameterCheck check;
  check.box("Bounds", this->Bounds, true);
  for (int axis = 0; axis < 3; ++axis)
  {
    check.inRange("Resolution", this->Resolution[axis], 2, 1024, "cells per axis");
  }
  if (!check.ok())
  {
    vtkErrorMacro(<< "Stable Fluids: " << check.problem());
    return false;
  }
  h = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    h = std::max(h, (this->Bounds[2 * axis + 1] - this->Bounds[2 * axis]) / this->Resolution[axis]);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double extent = this->Bounds[2 * axis + 1] - this->Bounds[2 * axis];
    cells[axis] = std::clamp(static_cast<int>(std::lround(extent / h)), 2, this->Resolution[axis]);
  }
  return true;
}

bool vtkPFStableFluids::CheckParameters()
{
  // The declared parameters' ranges are their declarations' (StableFluidsParameterTable.h).
  const std::string declared =
    parafluid::checkDeclared(parafluid::clouds::stableFluidsParameterTable(), this->Parameters);
  parafluid::vtk::ParameterCheck check;
  check.require(declared.empty(), declared)
    .inRange("TimeStep", this->TimeStep, 1e-6, 10.0, "s")
    .inRange("OutputInterval", this->OutputInterval, 1e-6, 1e6, "s")
    .inRange("NumberOfOutputs", this->NumberOfOutputs, 0, 100000)
    .allInRange("EmitterBox", this->EmitterBox, 6, -1e30, 1e30, "m")
    .inRange("CloudCoverage", this->CloudCoverage, 0.0, 1.0)
    .inRange("CloudFeatureSize", this->CloudFeatureSize, 1e-6, 1e7, "m")
    .require(this->OutputInterval / this->TimeStep <= 1e6,
             "OutputInterval / TimeStep is not allowed above a million steps per output (OutputInterval = " +
               parafluid::vtk::ParameterCheck::number(this->OutputInterval) +
               " s, TimeStep = " + parafluid::vtk::ParameterCheck::number(this->TimeStep) + " s)");
  if (!check.ok())
  {
    vtkErrorMacro(<< "Stable Fluids: " << check.problem());
    return false;
  }
  return true;
}

int vtkPFStableFluids::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int cells[3];
  double h;
  if (!this->GridShape(cells, h))
  {
    return 0;
  }
  const int extent[6] = { 0, cells[0] - 1, 0, cells[1] - 1, 0, cells[2] - 1 };
  const double origin[3] = { this->Bounds[0] + 0.5 * h, this->Bounds[2] + 0.5 * h, this->Bounds[4] + 0.5 * h };
  const double spacing[3] = { h, h, h };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  const double interval =
    this->OutputInterval > 0.0 && std::isfinite(this->OutputInterval) ? this->OutputInterval : 1.0;
  parafluid::vtk::setOutputTimes(outInfo, 0.0, interval, std::clamp(this->NumberOfOutputs, 0, 100000));
  return 1;
}

int vtkPFStableFluids::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole of the sources on every process (structured sources: their whole extent).
  if (vtkInformation* inInfo = inputVector[1]->GetInformationObject(0))
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
                  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    }
  }
  return 1;
}

namespace
{
vtkFloatArray* newArray(const char* name, int components, vtkIdType tuples)
{
  vtkFloatArray* array = vtkFloatArray::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}
} // namespace

int vtkPFStableFluids::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector)
{
  return parafluid::vtk::guardedRequest(
    this, "Stable Fluids",
    [&]() -> int
    {
      vtkInformation* outInfo = outputVector->GetInformationObject(0);
      vtkImageData* output = vtkImageData::GetData(outInfo);
      int cells[3];
      double h;
      if (!this->GridShape(cells, h))
      {
        return 0;
      }
      if (!this->CheckParameters())
      {
        return 0;
      }
      // One grid, on the first process: the others give an empty piece (so that under MPI the
      // cloud is neither simulated nor drawn twice).
      if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
          outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
      {
        output->Initialize();
        return 1;
      }
      const double interval = this->OutputInterval;
      const double cellCount = static_cast<double>(cells[0]) * cells[1] * cells[2];
      // Faces, cells, the pressure, the advection's and the solver's work arrays: ~40 doubles a cell.
      const std::string memory = parafluid::checkMemoryBudget(40.0 * 8.0 * cellCount, "the Stable Fluids grid");
      if (!memory.empty())
      {
        vtkErrorMacro(<< "Stable Fluids: " << memory << "; lower Resolution");
        return 0;
      }
      const std::optional<long long> requested =
        parafluid::vtk::requestedOutput(outInfo, 0.0, interval, this->NumberOfOutputs);
      if (!requested)
      {
        vtkErrorMacro(<< parafluid::vtk::notATimeError("Stable Fluids"));
        return 0;
      }
      const long long target = *requested;

      vtkDataSet* sources = vtkDataSet::GetData(inputVector[1]);
      Cache& cache = *this->Cached;
      cache.follow({ sources ? sources->GetMTime() : 0, this->GetMTime() });
      if (const KeptCloudInfo* kept = cache.restore(target, { output }))
      {
        this->LastSteps = kept->steps;
        this->LastIterations = kept->iterations;
        output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), target * interval);
        return 1;
      }
      if (!cache.canContinueTo(target))
      {
        cache.dropRun();
        StableFluidsParameters p = this->Parameters;
        std::copy(cells, cells + 3, p.resolution);
        p.cellSize = h;
        p.origin[0] = this->Bounds[0];
        p.origin[1] = this->Bounds[2];
        p.origin[2] = this->Bounds[4];
        p.macCormack = this->MacCormack;
        p.conservative = this->Conservative;
        for (int f = 0; f < 6; ++f)
        {
          p.open[f] = this->OpenFaces[f] != 0;
        }
        p.emitter = this->Emitter;
        std::copy(this->EmitterBox, this->EmitterBox + 6, p.emitterBox);
        p.preconditioner = this->Preconditioner == 1 ? parafluid::clouds::Preconditioner::Jacobi
                                                     : parafluid::clouds::Preconditioner::Multigrid;
        cache.start(std::make_unique<StableFluids>(p));
        if (this->ProceduralClouds)
        {
          parafluid::clouds::CloudShapeParameters shapes;
          shapes.coverage = this->CloudCoverage;
          shapes.featureSize = this->CloudFeatureSize;
          shapes.seed = static_cast<std::uint64_t>(this->CloudSeed);
          parafluid::clouds::fillCloudShapes(cache.simulation()->grid(), shapes);
        }
        if (sources && sources->GetNumberOfPoints() > 0)
        {
          // Every point, or with point scalars (a volume: a terrain's valleys, a mask) those
          // whose scalar is above 0.
          vtkDataArray* mask = sources->GetPointData()->GetScalars();
          std::vector<double> xyz;
          for (vtkIdType n = 0; n < sources->GetNumberOfPoints(); ++n)
          {
            if (mask && !(mask->GetComponent(n, 0) > 0.0))
            {
              continue;
            }
            double p[3];
            sources->GetPoint(n, p);
            xyz.insert(xyz.end(), p, p + 3);
          }
          cache.simulation()->setPointSources(std::move(xyz));
        }
        cache.Steps = 0;
      }
      const int advanced = this->AdvanceTo(target, cellCount);
      if (advanced <= 0)
      {
        return advanced < 0 ? 1 : 0; // aborted, or an error said why
      }
      cache.reached(target);
      this->LastSteps = cache.Steps;
      this->LastIterations = cache.simulation()->lastProjection().iterations;

      const StaggeredGrid& g = cache.simulation()->grid();
      output->SetExtent(0, g.nx - 1, 0, g.ny - 1, 0, g.nz - 1);
      output->SetOrigin(g.origin[0] + 0.5 * g.h, g.origin[1] + 0.5 * g.h, g.origin[2] + 0.5 * g.h);
      output->SetSpacing(g.h, g.h, g.h);
      const vtkIdType n = static_cast<vtkIdType>(g.cells());
      vtkFloatArray* density = newArray("density", 1, n);
      vtkFloatArray* temperature = newArray("temperature", 1, n);
      vtkFloatArray* velocity = newArray("velocity", 3, n);
      for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
          for (int i = 0; i < g.nx; ++i)
          {
            const vtkIdType id = static_cast<vtkIdType>(g.density.index(i, j, k));
            density->SetValue(id, static_cast<float>(g.density.values[id]));
            temperature->SetValue(id, static_cast<float>(g.temperature.values[id]));
            // At the centre: the mean of the two faces of each axis.
            velocity->SetTypedComponent(id, 0, static_cast<float>(0.5 * (g.u.at(i, j, k) + g.u.at(i + 1, j, k))));
            velocity->SetTypedComponent(id, 1, static_cast<float>(0.5 * (g.v.at(i, j, k) + g.v.at(i, j + 1, k))));
            velocity->SetTypedComponent(id, 2, static_cast<float>(0.5 * (g.w.at(i, j, k) + g.w.at(i, j, k + 1))));
          }
      vtkPointData* pd = output->GetPointData();
      pd->AddArray(density);
      pd->AddArray(temperature);
      pd->AddArray(velocity);
      pd->SetActiveScalars("density");
      pd->SetActiveVectors("velocity");
      density->Delete();
      temperature->Delete();
      velocity->Delete();
      if (this->OutputDivergence)
      {
        const std::vector<double> div = parafluid::clouds::divergence(g);
        vtkFloatArray* divergence = newArray("divergence", 1, n);
        for (vtkIdType id = 0; id < n; ++id)
        {
          divergence->SetValue(id, static_cast<float>(div[id]));
        }
        pd->AddArray(divergence);
        divergence->Delete();
      }
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), target * interval);
      cache.keep(target, { output }, { this->LastSteps, this->LastIterations });
      return 1;
    });
}

int vtkPFStableFluids::AdvanceTo(long long target, double cellCount)
{
  Cache& cache = *this->Cached;
  const double interval = this->OutputInterval;
  const long long intervals = target - cache.outputIndex();
  // Each output interval in equal steps no longer than TimeStep, and short enough that the
  // fastest flow crosses at most kMaxCellsPerStep cells a step (decided at the interval's start,
  // so the steps do not depend on which times were asked for before).
  const auto stepsFor = [this, interval](double longest)
  { return std::ceil(interval / std::min(this->TimeStep, longest) - 1e-9); };
  const double firstSteps = std::max(1.0, stepsFor(cache.simulation()->longestStableStep()));
  // The property that drives the count: the flow's speed where it forces shorter steps.
  const bool fastFlow = firstSteps > std::max(1.0, stepsFor(this->TimeStep));
  // Nominal cost on a 2-core machine: 0.14 us a cell per step (the 64^3 default's).
  parafluid::vtk::LongWork work(this, "Stable Fluids",
                                { static_cast<double>(intervals) * firstSteps * cellCount, 1.4e-7,
                                  "cell updates (cells x steps to the requested time)",
                                  fastFlow ? "EmitterSpeed" : "Resolution" });
  double done = 0.0;
  for (long long k = 0; k < intervals; ++k)
  {
    const double fastest = cache.simulation()->fastestSpeed();
    const double steps = std::max(1.0, stepsFor(cache.simulation()->longestStableStep()));
    if (steps > kMaxStepsPerOutput)
    {
      char text[400];
      std::snprintf(text, sizeof(text),
                    "Stable Fluids: the flow reaches %.4g m/s at t = %.3g s; to keep it within %g cells a step, "
                    "an OutputInterval of %.3g s would need %.3g steps (over %.0f): lower EmitterSpeed or the "
                    "buoyancy (BuoyancyHeat, BuoyancyDensity), or OutputInterval",
                    fastest, static_cast<double>(cache.outputIndex()) * interval,
                    parafluid::clouds::StableFluids::kMaxCellsPerStep, interval, steps, kMaxStepsPerOutput);
      vtkErrorMacro(<< text);
      cache.dropRun();
      return 0;
    }
    const double dt = interval / steps;
    for (long long s = 0; s < static_cast<long long>(steps); ++s)
    {
      cache.simulation()->step(dt);
      ++cache.Steps;
      done += cellCount;
      if (!work.advance(done))
      {
        cache.dropRun();
        return -1;
      }
    }
    cache.reached(cache.outputIndex() + 1);
  }
  return 1;
}

void vtkPFStableFluids::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution[0] << " " << this->Resolution[1] << " " << this->Resolution[2]
     << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
}
