#include "vtkPFSPHStep.h"

#include "vtkPFParticleArrays.h"
#include "vtkPFTriangleBoundary.h"

#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SPHSolver.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

using parafluid::ParticleState;
using parafluid::sph::PressureSolver;
using parafluid::sph::SPHParameters;
using parafluid::sph::SPHSolver;

struct vtkPFSPHStep::Cache
{
  std::optional<SPHSolver> Solver;
  long long OutputIndex = 0;   // the output time the solver's state belongs to
  vtkMTimeType InputTime = 0;  // the input data object's MTime it started from
  vtkMTimeType BoundaryTime = 0; // the boundary surface's MTime (0 without one)
  vtkMTimeType FilterTime = 0; // this filter's MTime (its properties) it started with
};

vtkStandardNewMacro(vtkPFSPHStep);

vtkPFSPHStep::vtkPFSPHStep()
  : Cached(std::make_unique<Cache>())
{
  this->SetNumberOfInputPorts(2);
}

vtkPFSPHStep::~vtkPFSPHStep() = default;

int vtkPFSPHStep::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkPFSPHStep::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  this->InputHasTime = inInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) &&
    inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) > 0;
  this->StartTime = this->InputHasTime ? inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[0] : 0.0;
  const double interval = this->OutputInterval > 0.0 ? this->OutputInterval : 1.0;
  std::vector<double> times(static_cast<std::size_t>(this->NumberOfOutputs) + 1);
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    times[k] = this->StartTime + static_cast<double>(k) * interval;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { times.front(), times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkPFSPHStep::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Whatever time is asked of this filter, the simulation starts from the input at t0.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (this->InputHasTime)
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), this->StartTime);
  }
  return 1;
}

namespace
{
/// Copies a 1- or 3-component input array into float vectors; false when absent or mis-shaped.
bool readComponents(vtkDataArray* array, int components, std::vector<float>* targets[])
{
  if (!array || array->GetNumberOfComponents() != components)
  {
    return false;
  }
  const vtkIdType n = array->GetNumberOfTuples();
  for (int c = 0; c < components; ++c)
  {
    targets[c]->resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      (*targets[c])[static_cast<std::size_t>(i)] = static_cast<float>(array->GetComponent(i, c));
    }
  }
  return true;
}
} // namespace

int vtkPFSPHStep::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* local = vtkPointSet::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  if (!local)
  {
    vtkErrorMacro("SPH Step: the input is not a point set (particles)");
    return 0;
  }
  this->StepsTakenLastUpdate = 0;
  // Under MPI the pieces are gathered on process 0, which simulates all particles (a particle
  // needs its neighbours from every piece; ghost exchange would let each process keep its own).
  bool simulatesHere = true;
  vtkSmartPointer<vtkDataObject> gathered = parafluid::vtk::gatherToFirstProcess(local, simulatesHere);
  if (!simulatesHere)
  {
    output->Initialize();
    return 1;
  }
  vtkPointSet* input = vtkPointSet::SafeDownCast(gathered);
  // The gathered copy is new on every update; the input's own MTime says whether it changed.
  const vtkMTimeType inputTime = local->GetMTime();
  if (!(this->OutputInterval > 0.0) || !std::isfinite(this->OutputInterval))
  {
    vtkErrorMacro("SPH Step: OutputInterval must be a positive number of seconds, got " << this->OutputInterval);
    return 0;
  }
  const double interval = this->OutputInterval;
  long long target = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) && interval > 0.0)
  {
    const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    target = std::llround((t - this->StartTime) / interval);
    target = std::max(0LL, std::min<long long>(target, this->NumberOfOutputs));
  }

  vtkPolyData* surface = vtkPolyData::GetData(inputVector[1]);
  const vtkMTimeType boundaryTime = surface ? surface->GetMTime() : 0;

  Cache& cache = *this->Cached;
  const bool reusable = cache.Solver && cache.InputTime == inputTime && cache.BoundaryTime == boundaryTime &&
    cache.FilterTime == this->GetMTime() && cache.OutputIndex <= target;
  if (!reusable)
  {
    cache.Solver.reset();
    vtkFieldData* fd = input->GetFieldData();
    const double spacing = parafluid::vtk::fieldValue(fd, "particle_spacing", 0.0);
    SPHParameters p;
    p.smoothingLength = static_cast<float>(this->SmoothingLength > 0.0
        ? this->SmoothingLength
        : parafluid::vtk::fieldValue(fd, "smoothing_length", 2.0 * spacing));
    p.restDensity = static_cast<float>(this->RestDensity);
    p.gasStiffness = static_cast<float>(this->GasStiffness);
    p.pressureSolver = this->PressureSolver == 1 ? PressureSolver::DFSPH : PressureSolver::WCSPH;
    p.viscosity = static_cast<float>(this->Viscosity);
    p.surfaceTension = static_cast<float>(this->SurfaceTension);
    p.adaptiveTimeStep = this->AdaptiveTimeStep;
    p.cflNumber = static_cast<float>(this->CFLNumber);
    p.maxTimeStep = static_cast<float>(this->MaxTimeStep);
    p.timeStep = static_cast<float>(this->TimeStep);
    p.densityTolerance = static_cast<float>(this->DensityTolerance);
    p.maxPressureIterations = this->MaxPressureIterations;
    p.wallRestitution = static_cast<float>(this->WallRestitution);
    p.wallFriction = this->WallFriction == 2 ? parafluid::sph::WallFriction::LogLaw
      : this->WallFriction == 1              ? parafluid::sph::WallFriction::NoSlip
                                             : parafluid::sph::WallFriction::FreeSlip;
    for (int k = 0; k < 6; ++k)
    {
      p.frictionWalls[k] = this->FrictionWalls[k] != 0;
    }
    p.wallKinematicViscosity = static_cast<float>(this->WallKinematicViscosity);
    p.boundaryDamping = static_cast<float>(this->BoundaryDamping);
    for (int a = 0; a < 3; ++a)
    {
      p.gravity[a] = static_cast<float>(this->Gravity[a]);
    }
    const bool domainGiven = std::any_of(this->DomainBounds, this->DomainBounds + 6, [](double v) { return v != 0.0; });
    vtkDataArray* domain = vtkArrayDownCast<vtkDataArray>(fd ? fd->GetAbstractArray("domain_bounds") : nullptr);
    if (!domainGiven && !(domain && domain->GetNumberOfValues() == 6))
    {
      vtkErrorMacro("SPH Step: set DomainBounds (xmin xmax ymin ymax zmin zmax, metres); the input has no "
                    "domain_bounds field data to take them from");
      return 0;
    }
    for (int k = 0; k < 6; ++k)
    {
      p.domainBounds[k] = static_cast<float>(domainGiven ? this->DomainBounds[k] : domain->GetComponent(k / domain->GetNumberOfComponents(), k % domain->GetNumberOfComponents()));
    }
    if (this->ParticleMass > 0.0)
    {
      p.particleMass = static_cast<float>(this->ParticleMass);
    }
    else if (spacing > 0.0 && p.smoothingLength > 0.0f)
    {
      try
      {
        p.particleMass = parafluid::sph::latticeParticleMass(
          static_cast<float>(spacing), p.smoothingLength, p.restDensity, p.densityKernel());
      }
      catch (const std::exception& e)
      {
        vtkErrorMacro("SPH Step: " << e.what());
        return 0;
      }
    }
    else
    {
      vtkErrorMacro("SPH Step: set ParticleMass (kg) and SmoothingLength (m); the input has no particle_spacing "
                    "field data to derive them from");
      return 0;
    }

    ParticleState state;
    const vtkIdType n = input->GetNumberOfPoints();
    state.x.resize(static_cast<std::size_t>(n));
    state.y.resize(static_cast<std::size_t>(n));
    state.z.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      input->GetPoint(i, x);
      state.x[i] = static_cast<float>(x[0]);
      state.y[i] = static_cast<float>(x[1]);
      state.z[i] = static_cast<float>(x[2]);
    }
    std::vector<float>* velocity[3] = { &state.vx, &state.vy, &state.vz };
    readComponents(input->GetPointData()->GetArray("velocity"), 3, velocity);
    if (vtkDataArray* ids = input->GetPointData()->GetArray("id"))
    {
      state.id.resize(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        state.id[i] = static_cast<std::int64_t>(ids->GetComponent(i, 0));
      }
    }
    std::shared_ptr<const parafluid::TriangleBoundary> boundary;
    if (surface)
    {
      std::string problem;
      boundary = parafluid::vtk::makeTriangleBoundary(surface, problem);
      if (!boundary)
      {
        vtkErrorMacro("SPH Step: " << problem);
        return 0;
      }
    }
    try
    {
      cache.Solver.emplace(p, std::move(state), std::move(boundary));
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro("SPH Step: " << e.what());
      return 0;
    }
    cache.OutputIndex = 0;
    cache.InputTime = inputTime;
    cache.BoundaryTime = boundaryTime;
    cache.FilterTime = this->GetMTime();
  }

  // Advance from the cached output time to the requested one, one output interval at a time, so
  // that the steps taken (and so the result) do not depend on which times were asked for before.
  try
  {
    bool aborted = false;
    const long long intervals = target - cache.OutputIndex;
    for (long long k = 0; k < intervals && !aborted; ++k)
    {
      this->StepsTakenLastUpdate += cache.Solver->advance(interval,
        [this, &aborted, k, intervals](double fraction)
        {
          this->UpdateProgress((static_cast<double>(k) + fraction) / static_cast<double>(intervals));
          aborted = this->CheckAbort() != 0;
          return !aborted;
        });
    }
    if (aborted)
    {
      // The state is between output times now; drop it so the next update starts cleanly.
      cache.Solver.reset();
      return 1;
    }
  }
  catch (const std::exception& e)
  {
    cache.Solver.reset();
    vtkErrorMacro("SPH Step: " << e.what());
    return 0;
  }
  this->MeanDensityError = cache.Solver->lastStep().meanCompression;
  cache.OutputIndex = target;

  // Output in the input's order and with the input's other arrays.
  const ParticleState& s = cache.Solver->state();
  const auto n = static_cast<vtkIdType>(s.size());
  output->GetPointData()->ShallowCopy(input->GetPointData());
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(n);
  auto vector3 = [&](const char* name) {
    vtkNew<vtkFloatArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(n);
    output->GetPointData()->AddArray(a);
    return a->GetPointer(0);
  };
  auto scalar = [&](const char* name) {
    vtkNew<vtkFloatArray> a;
    a->SetName(name);
    a->SetNumberOfValues(n);
    output->GetPointData()->AddArray(a);
    return a->GetPointer(0);
  };
  float* position = coordinates->GetPointer(0);
  float* velocityOut = vector3("velocity");
  float* density = scalar("density");
  // Optional arrays: without them the input's arrays of that name (if any) are dropped too, as they
  // would describe the start time.
  float* acceleration = nullptr;
  float* pressure = nullptr;
  output->GetPointData()->RemoveArray("acceleration");
  output->GetPointData()->RemoveArray("pressure");
  if (this->OutputAcceleration)
  {
    acceleration = vector3("acceleration");
  }
  std::vector<float> pressureField;
  if (this->OutputPressure)
  {
    pressure = scalar("pressure");
    pressureField = cache.Solver->smoothedPressure();
  }
  std::vector<std::uint32_t> neighbours;
  vtkNew<vtkIntArray> neighbourCount;
  if (this->OutputNeighbourCount)
  {
    neighbours = cache.Solver->neighbourCounts();
    neighbourCount->SetName("neighbour_count");
    neighbourCount->SetNumberOfValues(n);
    output->GetPointData()->AddArray(neighbourCount);
  }
  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName("id");
  ids->SetNumberOfValues(n);
  output->GetPointData()->AddArray(ids);
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType i = s.originalIndex[k];
    position[3 * i + 0] = s.x[k];
    position[3 * i + 1] = s.y[k];
    position[3 * i + 2] = s.z[k];
    velocityOut[3 * i + 0] = s.vx[k];
    velocityOut[3 * i + 1] = s.vy[k];
    velocityOut[3 * i + 2] = s.vz[k];
    if (acceleration)
    {
      acceleration[3 * i + 0] = s.ax[k];
      acceleration[3 * i + 1] = s.ay[k];
      acceleration[3 * i + 2] = s.az[k];
    }
    if (pressure)
    {
      pressure[i] = pressureField[k];
    }
    if (!neighbours.empty())
    {
      neighbourCount->SetValue(i, static_cast<int>(neighbours[k]));
    }
    density[i] = s.density[k];
    ids->SetValue(i, s.id[k]);
  }
  output->GetPointData()->SetActiveVectors("velocity");
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  parafluid::vtk::setOneVertexPerPoint(output, n);

  const double time = this->StartTime + static_cast<double>(target) * interval;
  const SPHParameters& p = cache.Solver->parameters();
  const double h = p.smoothingLength, rho0 = p.restDensity, mass = p.particleMass;
  const double bounds[6] = { p.domainBounds[0], p.domainBounds[1], p.domainBounds[2], p.domainBounds[3],
    p.domainBounds[4], p.domainBounds[5] };
  vtkFieldData* fd = output->GetFieldData();
  parafluid::vtk::setFieldValue(fd, "time", &time, 1);
  parafluid::vtk::setFieldValue(fd, "smoothing_length", &h, 1);
  parafluid::vtk::setFieldValue(fd, "rest_density", &rho0, 1);
  parafluid::vtk::setFieldValue(fd, "particle_mass", &mass, 1);
  parafluid::vtk::setFieldValue(fd, "domain_bounds", bounds, 6);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}

void vtkPFSPHStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SmoothingLength: " << this->SmoothingLength << "\n";
  os << indent << "PressureSolver: " << (this->PressureSolver == 1 ? "DFSPH" : "WCSPH") << "\n";
  os << indent << "AdaptiveTimeStep: " << this->AdaptiveTimeStep << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "OutputInterval: " << this->OutputInterval << "\n";
}
