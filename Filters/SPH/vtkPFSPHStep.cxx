#include "vtkPFSPHStep.h"

#include "DistributedStep.h"
#include "EnumerationChoice.h"
#include "GuardedRequest.h"
#include "LongWork.h"
#include "OutputTimes.h"
#include "ParticleArrays.h"
#include "ParticleStateArrays.h"
#include "TimeSteppedCache.h"
#include "TriangleBoundaryFromSurface.h"

#include "HeightImage.h"
#include "ProcessCommunicator.h"
#include "parafluid/common/MemoryBudget.h"
#include "vtkImageData.h"

#include "parafluid/sph/DistributedSimulation.h"
#include "parafluid/sph/SPHParameterTable.h"
#include "parafluid/sph/Simulation.h"
#include "parafluid/sph/SolverRegistry.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>

namespace contract = parafluid::contract;
using parafluid::sph::Simulation;
using parafluid::sph::SPHParameters;
using parafluid::sph::WallFriction;

// What an output kept by the cache reports again when it is asked for a second time.
struct KeptOutputInfo
{
  double meanDensityError = 0.0;
};

struct vtkPFSPHStep::Cache : parafluid::vtk::TimeSteppedCache<Simulation, KeptOutputInfo>
{
};

vtkStandardNewMacro(vtkPFSPHStep);

vtkPFSPHStep::vtkPFSPHStep()
  : vtkPFParticleAlgorithm("SPH Step")
  , Cached(std::make_unique<Cache>())
{
  this->SetNumberOfInputPorts(2);
  // A simulation cannot start from NaN: refused, naming the particle.
  this->SetNonFinitePolicy(NonFinite::Refuse, { parafluid::contract::Velocity });
  // Zero: taken from the input's field data when the simulation starts.
  this->Parameters.smoothingLength = 0.0f;
  this->Parameters.particleMass = 0.0f;
  this->Parameters.domainBounds.fill(0.0f);
}

void vtkPFSPHStep::SetPressureSolver(int solver)
{
  const parafluid::sph::SolverEntry* entry = parafluid::sph::solverForPropertyValue(solver);
  if (!entry)
  {
    vtkErrorMacro(<< "PressureSolver = " << solver << " is not a solver; kept "
                  << parafluid::sph::solverEntry(this->Parameters.pressureSolver).label);
    return;
  }
  this->SetParameter(this->Parameters.pressureSolver, entry->type);
}

void vtkPFSPHStep::SetBackend(int backend)
{
  if (backend != this->Backend &&
      parafluid::vtk::isChoice(this, "Backend", backend, { "Automatic", "CPU", "CUDA" }, this->Backend))
  {
    this->Backend = backend;
    this->Modified();
  }
}

int vtkPFSPHStep::GetPressureSolver() const
{
  return parafluid::sph::solverEntry(this->Parameters.pressureSolver).propertyValue;
}

void vtkPFSPHStep::SetSurfaceTensionModel(int model)
{
  if (parafluid::vtk::isChoice(this, "SurfaceTensionModel", model,
                               { "Colour field (Müller)", "Akinci 2013", "Akinci 2013, cohesion only" },
                               static_cast<int>(this->Parameters.surfaceTensionModel)))
  {
    this->SetParameter(this->Parameters.surfaceTensionModel, static_cast<parafluid::sph::SurfaceTensionModel>(model));
  }
}

void vtkPFSPHStep::SetPeriodicAxes(int x, int y, int z)
{
  const int axes[3] = { x, y, z };
  for (int a = 0; a < 3; ++a)
  {
    this->SetParameter(this->Parameters.periodic[a], axes[a] != 0);
  }
}

void vtkPFSPHStep::SetWallFriction(int friction)
{
  if (parafluid::vtk::isChoice(this, "WallFriction", friction,
                               { "Free-slip", "No-slip (viscous)", "Turbulent (law of the wall)" },
                               static_cast<int>(this->Parameters.wallFriction)))
  {
    this->SetParameter(this->Parameters.wallFriction, static_cast<WallFriction>(friction));
  }
}

void vtkPFSPHStep::SetWallRestitution(double value)
{
  this->SetParameter(this->Parameters.wallRestitution, value); // checked when the run starts
}

void vtkPFSPHStep::SetGravity(double x, double y, double z)
{
  const double g[3] = { x, y, z };
  for (int a = 0; a < 3; ++a)
  {
    this->SetParameter(this->Parameters.gravity[a], g[a]);
  }
}

void vtkPFSPHStep::SetDomainBounds(double x0, double x1, double y0, double y1, double z0, double z1)
{
  const double b[6] = { x0, x1, y0, y1, z0, z1 };
  for (int k = 0; k < 6; ++k)
  {
    this->SetParameter(this->Parameters.domainBounds[k], b[k]);
  }
}

void vtkPFSPHStep::SetFrictionWalls(int x0, int x1, int y0, int y1, int z0, int z1)
{
  const int walls[6] = { x0, x1, y0, y1, z0, z1 };
  for (int k = 0; k < 6; ++k)
  {
    this->SetParameter(this->Parameters.frictionWalls[k], walls[k] != 0);
  }
}

vtkPFSPHStep::~vtkPFSPHStep() = default;

int vtkPFSPHStep::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkPFSPHStep::RequestInformation(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  this->InputHasTime = inInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) &&
                       inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) > 0;
  this->StartTime = this->InputHasTime ? inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[0] : 0.0;
  if (this->NumberOfOutputs < 0 || this->NumberOfOutputs > 100000)
  {
    this->ReportError("NumberOfOutputs = " + std::to_string(this->NumberOfOutputs) +
                      " is not allowed: it must be from 0 to 100000 (output times offered)");
    return 0;
  }
  const double interval = this->OutputInterval > 0.0 ? this->OutputInterval : 1.0;
  parafluid::vtk::setOutputTimes(outInfo, this->StartTime, interval, this->NumberOfOutputs);
  return 1;
}

int vtkPFSPHStep::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Whatever time is asked of this filter, the simulation starts from the input at t0.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (this->InputHasTime)
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), this->StartTime);
  }
  return 1;
}

int vtkPFSPHStep::RequestParticles(const Particles& particles, vtkInformationVector** inputVector,
                                   vtkInformation* outInfo, vtkPolyData* output)
{
  this->StepsTakenLastUpdate = 0;
  if (!(this->OutputInterval > 0.0) || !std::isfinite(this->OutputInterval))
  {
    this->ReportError("OutputInterval must be a positive number of seconds, got " +
                      std::to_string(this->OutputInterval));
    return 0;
  }
  const std::optional<long long> requested =
    parafluid::vtk::requestedOutput(outInfo, this->StartTime, this->OutputInterval, this->NumberOfOutputs);
  if (!requested)
  {
    this->ReportError(parafluid::vtk::notATimeError("SPH Step"));
    return 0;
  }
  const long long target = *requested;
  // Moving forward under the same inputs and properties continues the cached simulation, and an
  // output already made is copied. The gathered copy is new on every update; the local input's
  // own MTime says whether it changed.
  Cache& cache = *this->Cached;
  vtkDataObject* boundaryData = vtkDataObject::GetData(inputVector[1]);
  cache.follow({ particles.Local->GetMTime(), boundaryData ? boundaryData->GetMTime() : 0, this->GetMTime() });
  // A distributed run's processes restore, continue or restart together.
  const bool distributed = this->WorksOnPieces() && parafluid::vtk::processCount() > 1;
  auto together = [distributed](bool ok) { return distributed ? parafluid::vtk::agreeOnAllProcesses(ok) : ok; };
  const KeptOutputInfo* kept = cache.restore(target, { output });
  if (together(kept != nullptr))
  {
    this->MeanDensityError = kept->meanDensityError;
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(),
                                  this->StartTime + static_cast<double>(target) * this->OutputInterval);
    return 1;
  }
  if (!together(cache.canContinueTo(target)))
  {
    vtkSmartPointer<vtkPolyData> boundary;
    if (distributed)
    {
      const vtkSmartPointer<vtkDataObject> whole = parafluid::vtk::boundaryOnEveryProcess(boundaryData);
      const bool read = this->ReadBoundary(whole, boundary);
      if (!this->StartDistributed(particles.Gathered, boundary, read))
      {
        return 0;
      }
    }
    else if (!this->ReadBoundary(boundaryData, boundary) || !this->StartSimulation(particles.Gathered, boundary))
    {
      return 0;
    }
  }
  const int advanced = this->AdvanceTo(target);
  if (advanced != 1)
  {
    return advanced < 0 ? 1 : 0; // an abort is no error, and leaves the output empty
  }
  this->WriteOutput(particles.Gathered, target, output);
  cache.keep(target, { output }, { this->MeanDensityError });
  return 1;
}

bool vtkPFSPHStep::ReadBoundary(vtkDataObject* boundaryData, vtkSmartPointer<vtkPolyData>& boundary)
{
  // The Boundary: a surface, or a terrain's 2-D height image (made into its warped surface).
  boundary = vtkPolyData::SafeDownCast(boundaryData);
  if (auto* image = vtkImageData::SafeDownCast(boundaryData))
  {
    parafluid::vtk::HeightImage heights;
    std::string problem;
    if (!parafluid::vtk::readHeightImage(image, "", heights, problem))
    {
      this->ReportError("Boundary: " + problem);
      return false;
    }
    const auto bad =
      std::find_if(heights.heights.begin(), heights.heights.end(), [](float h) { return !std::isfinite(h); });
    if (bad != heights.heights.end())
    {
      this->ReportError("Boundary: the height image's '" + heights.arrayName + "' is not finite at sample " +
                        std::to_string(bad - heights.heights.begin()) +
                        " (fill no-data with Terrain From Image first)");
      return false;
    }
    boundary = parafluid::vtk::heightSurface(heights.heights, heights.nx, heights.ny, heights.origin, heights.spacing);
  }
  return true;
}

bool vtkPFSPHStep::ResolveParameters(vtkFieldData* fd, SPHParameters& p)
{
  p = this->Parameters;
  // The properties the core does not check itself, or whose 0 means "automatic" (the core sees
  // only the resolved value).
  const double domainProperty[6] = { p.domainBounds[0], p.domainBounds[1], p.domainBounds[2],
                                     p.domainBounds[3], p.domainBounds[4], p.domainBounds[5] };
  const bool automaticDomain = std::all_of(domainProperty, domainProperty + 6, [](double v) { return v == 0.0; });
  const double gravity[3] = { p.gravity[0], p.gravity[1], p.gravity[2] };
  // The SPH parameters' ranges are their declarations' (SPHParameterTable.h); 0 asks for the
  // smoothing length and the mass from the input.
  parafluid::vtk::ParameterCheck check;
  const std::string range = parafluid::sph::checkParameterRanges(p, { "SmoothingLength", "ParticleMass" });
  check.require(range.empty(), range)
    .allInRange("Gravity", gravity, 3, -1e6, 1e6, "m/s^2")
    .inRange("OutputInterval", this->OutputInterval, 1e-9, 1e6, "s");
  if (!automaticDomain)
  {
    check.box("DomainBounds", domainProperty, true);
  }
  if (!this->Accept(check))
  {
    return false;
  }
  if (!p.adaptiveTimeStep && p.timeStep > this->OutputInterval)
  {
    // Fixed steps land exactly on every output time, so none is longer than OutputInterval.
    vtkWarningMacro(<< "SPH Step: TimeStep (" << p.timeStep << " s) is longer than OutputInterval ("
                    << this->OutputInterval << " s): each step is " << this->OutputInterval << " s long");
  }
  const double spacing = parafluid::vtk::fieldValue(fd, contract::ParticleSpacing, 0.0);
  if (!(p.smoothingLength > 0.0f))
  {
    p.smoothingLength =
      parafluid::sph::defaultSmoothingLength(parafluid::sph::solverEntry(p.pressureSolver), spacing,
                                             parafluid::vtk::fieldValue(fd, contract::SmoothingLength, 0.0));
  }
  const bool domainGiven = std::any_of(p.domainBounds.begin(), p.domainBounds.end(), [](float v) { return v != 0.0f; });
  vtkDataArray* domain = vtkArrayDownCast<vtkDataArray>(fd ? fd->GetAbstractArray(contract::DomainBounds) : nullptr);
  if (!domainGiven)
  {
    if (!(domain && domain->GetNumberOfValues() == 6))
    {
      this->ReportError("set DomainBounds (xmin xmax ymin ymax zmin zmax, metres); the input has no domain_bounds "
                        "field data to take them from");
      return false;
    }
    const int components = domain->GetNumberOfComponents();
    for (int k = 0; k < 6; ++k)
    {
      p.domainBounds[k] = static_cast<float>(domain->GetComponent(k / components, k % components));
    }
  }
  if (p.particleMass > 0.0f)
  {
    return true;
  }
  if (!(spacing > 0.0 && p.smoothingLength > 0.0f))
  {
    this->ReportError("set ParticleMass (kg) and SmoothingLength (m); the input has no particle_spacing field data "
                      "to derive them from");
    return false;
  }
  try
  {
    p.particleMass = parafluid::sph::latticeParticleMass(static_cast<float>(spacing), p.smoothingLength, p.restDensity,
                                                         p.densityKernel());
  }
  catch (const std::exception& e)
  {
    this->ReportError(parafluid::vtk::exceptionText(e));
    return false;
  }
  return true;
}

void vtkPFSPHStep::WarnOfUnvalidatedSurfaceTension(const SPHParameters& p)
{
  // DFSPH's density solve corrects compression only, so it does not hold the under-dense surface
  // layer that Akinci's forces pull in; where those forces outweigh gravity at the particle scale
  // a resting millimetre drop boils (Testing/Benchmarks/README.md, "Akinci's curvature term,
  // landed"). δ-SPH holds it.
  const parafluid::sph::SolverEntry& solver = parafluid::sph::solverEntry(p.pressureSolver);
  const bool akinci = p.surfaceTensionModel != parafluid::sph::SurfaceTensionModel::ColourField;
  if (solver.holdsStrongCohesion || !akinci || !(p.surfaceTension > 0.0f))
  {
    return;
  }
  const double capillary = p.surfaceTension / (p.restDensity * p.smoothingLength * p.smoothingLength);
  const double gravity =
    std::sqrt(p.gravity[0] * p.gravity[0] + p.gravity[1] * p.gravity[1] + p.gravity[2] * p.gravity[2]);
  if (capillary > gravity)
  {
    vtkWarningMacro(<< "SPH Step: with " << solver.label
                    << ", Akinci surface tension that outweighs gravity at the particle scale "
                       "(SurfaceTension / (RestDensity SmoothingLength^2) = "
                    << capillary << " m/s^2, gravity " << gravity
                    << " m/s^2) is not validated: a resting drop boils. Choose δ-SPH as PressureSolver for surface "
                       "tension at this scale.");
  }
}

bool vtkPFSPHStep::StartSimulation(vtkPointSet* input, vtkPolyData* surface)
{
  Cache& cache = *this->Cached;
  cache.dropRun();
  SPHParameters p;
  if (!this->ResolveParameters(input->GetFieldData(), p))
  {
    return false;
  }
  this->WarnOfUnvalidatedSurfaceTension(p);
  // The solver (85 bytes a particle for WCSPH in the benchmarks, more for DFSPH) and the output's
  // arrays: 200 bytes a particle, checked before anything is allocated.
  const std::string memory =
    parafluid::checkMemoryBudget(200.0 * static_cast<double>(input->GetNumberOfPoints()),
                                 "simulating " + std::to_string(input->GetNumberOfPoints()) + " particles");
  if (!memory.empty())
  {
    this->ReportError(memory);
    return false;
  }
  std::shared_ptr<const parafluid::TriangleBoundary> boundary;
  if (surface)
  {
    std::string problem;
    boundary = parafluid::vtk::makeTriangleBoundary(surface, problem);
    if (!boundary)
    {
      this->ReportError(problem);
      return false;
    }
  }
  try
  {
    std::string choice;
    cache.start(parafluid::sph::makeSimulation(p, parafluid::vtk::readParticleState(input), std::move(boundary),
                                               static_cast<parafluid::sph::Backend>(this->Backend), &choice));
    if (this->Backend == 0 && choice != this->BackendUsed)
    {
      // Automatic says once where it runs, and for the CPU why not on the GPU.
      vtkOutputWindowDisplayText(("SPH Step runs on " + choice + "\n").c_str());
    }
    this->BackendUsed = choice;
  }
  catch (const std::exception& e)
  {
    this->ReportError(parafluid::vtk::exceptionText(e));
    return false;
  }
  return true;
}

bool vtkPFSPHStep::WorksOnPieces() const
{
  return parafluid::vtk::processCount() > 1 && this->Backend != static_cast<int>(parafluid::sph::Backend::CUDA) &&
         parafluid::sph::distributedRunLacks(this->Parameters).empty();
}

bool vtkPFSPHStep::StartDistributed(vtkPointSet* piece, vtkPolyData* surface, bool boundaryRead)
{
  Cache& cache = *this->Cached;
  cache.dropRun();
  if (!this->Processes)
  {
    this->Processes = parafluid::vtk::makeProcessCommunicator();
  }
  parafluid::Communicator& processes = *this->Processes;
  // The processes whose piece has particles resolve the automatic parameters from its field data
  // (process 0 too when none has any); the lowest that did gives them to all.
  const vtkIdType n = piece->GetNumberOfPoints();
  const double anyParticles = processes.reduce(static_cast<double>(n), parafluid::Reduction::Max);
  SPHParameters p = this->Parameters;
  int resolved = -1;
  if (n > 0 || (anyParticles == 0.0 && processes.rank() == 0))
  {
    resolved = this->ResolveParameters(piece->GetFieldData(), p) ? 1 : 0;
  }
  if (!parafluid::vtk::agreeOnParameters(p, resolved, processes))
  {
    return false;
  }
  if (processes.rank() == 0)
  {
    this->WarnOfUnvalidatedSurfaceTension(p);
  }
  // This process's share, the solver's and the ghosts' bytes (at most twice the share), checked
  // before anything is allocated.
  std::string problem = parafluid::checkMemoryBudget(400.0 * static_cast<double>(n),
                                                     "simulating " + std::to_string(n) + " particles on process " +
                                                       std::to_string(processes.rank()));
  std::shared_ptr<const parafluid::TriangleBoundary> boundary;
  if (problem.empty() && boundaryRead && surface)
  {
    boundary = parafluid::vtk::makeTriangleBoundary(surface, problem);
  }
  if (!problem.empty())
  {
    this->ReportError(problem);
  }
  if (!parafluid::vtk::agreeOnAllProcesses(boundaryRead && problem.empty()))
  {
    return false;
  }
  try
  {
    cache.start(parafluid::sph::makeDistributedSimulation(p, parafluid::vtk::readParticleState(piece),
                                                          std::move(boundary), processes));
  }
  catch (const std::exception& e)
  {
    this->ReportError(parafluid::vtk::exceptionText(e)); // every process throws together
    return false;
  }
  const std::string choice =
    std::string(cache.simulation()->backendName()) + " over " + std::to_string(processes.size()) + " processes";
  if (processes.rank() == 0 && choice != this->BackendUsed)
  {
    vtkOutputWindowDisplayText(("SPH Step runs on " + choice + "\n").c_str());
  }
  this->BackendUsed = choice;
  return true;
}

int vtkPFSPHStep::AdvanceTo(long long target)
{
  // One output interval at a time, so that the steps taken (and so the result) do not depend on
  // which times were asked for before.
  Cache& cache = *this->Cached;
  Simulation& simulation = *cache.simulation();
  const long long intervals = target - cache.outputIndex();
  // The first step's length says how many the requested time needs, at a nominal 1 us a
  // particle-step on a 2-core machine (delta-SPH's 1 M particle-steps/s).
  const double proposed = simulation.proposedTimeStep();
  const double steps = std::ceil(static_cast<double>(intervals) * this->OutputInterval /
                                 (proposed > 0.0 ? std::min(proposed, this->OutputInterval) : this->OutputInterval));
  const double perStep = static_cast<double>(std::max<std::size_t>(simulation.hostState().size(), 1));
  char what[160];
  std::snprintf(what, sizeof(what), "particle-steps (%.3g time steps of %.3g s for %.0f particles)", steps, proposed,
                perStep);
  parafluid::vtk::LongWork work(this, "SPH Step",
                                { steps * perStep, 1e-6, what, "the requested time",
                                  "the step shrinks with a high Viscosity, a small SmoothingLength or a large "
                                  "GasStiffness" });
  const double perInterval = steps * perStep / static_cast<double>(std::max(intervals, 1LL));
  bool aborted = false;
  try
  {
    for (long long k = 0; k < intervals && !aborted; ++k)
    {
      this->StepsTakenLastUpdate +=
        simulation.advance(this->OutputInterval,
                           [&work, &aborted, k, perInterval](double fraction)
                           {
                             aborted = !work.advance((static_cast<double>(k) + fraction) * perInterval);
                             return !aborted;
                           });
    }
  }
  catch (const std::exception& e)
  {
    cache.dropRun();
    this->ReportError(parafluid::vtk::exceptionText(e));
    return 0;
  }
  if (aborted)
  {
    cache.dropRun(); // it is between output times now
    return -1;
  }
  this->MeanDensityError = simulation.lastStep().meanCompression;
  cache.reached(target);
  return 1;
}

void vtkPFSPHStep::WriteOutput(vtkPointSet* input, long long target, vtkPolyData* output)
{
  // Output in the input's order and with the input's other arrays.
  const Simulation& solver = *this->Cached->simulation();
  // A distributed run's process holds other particles than its input piece: only the simulated
  // arrays go out, listed by id.
  const bool distributed = this->Processes && this->WorksOnPieces();
  if (!distributed)
  {
    output->GetPointData()->ShallowCopy(input->GetPointData());
  }
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  std::vector<float> pressure;
  std::vector<std::uint32_t> neighbours;
  parafluid::vtk::ParticleOutputArrays extra;
  extra.acceleration = this->OutputAcceleration;
  if (this->OutputPressure)
  {
    pressure = solver.smoothedPressure();
    extra.pressure = &pressure;
  }
  if (this->OutputNeighbourCount)
  {
    neighbours = solver.neighbourCounts();
    extra.neighbourCount = &neighbours;
  }
  if (distributed)
  {
    parafluid::vtk::writeParticleState(parafluid::vtk::ownParticlesInIdOrder(solver.hostState()), extra, output);
  }
  else
  {
    parafluid::vtk::writeParticleState(solver.hostState(), extra, output);
  }

  const double time = this->StartTime + static_cast<double>(target) * this->OutputInterval;
  const SPHParameters& p = solver.parameters();
  const double h = p.smoothingLength, rho0 = p.restDensity, mass = p.particleMass;
  const double bounds[6] = { p.domainBounds[0], p.domainBounds[1], p.domainBounds[2],
                             p.domainBounds[3], p.domainBounds[4], p.domainBounds[5] };
  vtkFieldData* fd = output->GetFieldData();
  parafluid::vtk::setFieldValue(fd, contract::Time, &time, 1);
  parafluid::vtk::setFieldValue(fd, contract::SmoothingLength, &h, 1);
  parafluid::vtk::setFieldValue(fd, contract::RestDensity, &rho0, 1);
  parafluid::vtk::setFieldValue(fd, contract::ParticleMass, &mass, 1);
  parafluid::vtk::setFieldValue(fd, contract::DomainBounds, bounds, 6);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
}

void vtkPFSPHStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SmoothingLength: " << this->Parameters.smoothingLength << "\n";
  os << indent << "PressureSolver: " << parafluid::sph::solverEntry(this->Parameters.pressureSolver).label << "\n";
  os << indent << "Backend: " << this->Backend << " (used: " << this->BackendUsed << ")\n";
  os << indent << "AdaptiveTimeStep: " << this->Parameters.adaptiveTimeStep << "\n";
  os << indent << "TimeStep: " << this->Parameters.timeStep << "\n";
  os << indent << "OutputInterval: " << this->OutputInterval << "\n";
}
