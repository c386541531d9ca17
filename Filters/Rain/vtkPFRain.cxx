#include "vtkPFRain.h"

#include "EnumerationChoice.h"
#include "GuardedRequest.h"
#include "HeightImage.h"
#include "LongWork.h"
#include "OutputTimes.h"
#include "ParameterCheck.h"
#include "ParticleArrays.h"
#include "ParticleContract.h"
#include "ParticleStateArrays.h"

#include "TimeSteppedCache.h"
#include "parafluid/common/MemoryBudget.h"
#include "parafluid/rain/RainField.h"
#include "parafluid/rain/RunoffParameterTable.h"
#include "parafluid/sph/SPHParameterTable.h"
#include "parafluid/sph/Simulation.h"
#include "parafluid/sph/SolverRegistry.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace contract = parafluid::contract;
using parafluid::HeightField;
using parafluid::rain::Impact;
using parafluid::rain::RainField;
using parafluid::rain::Runoff;

// What an output kept by the cache reports again when it is asked for a second time.
struct KeptRainInfo
{
  vtkIdType drops = 0;
  double fallen = 0.0, water = 0.0, infiltrated = 0.0;
};

struct vtkPFRain::Cache : parafluid::vtk::TimeSteppedCache<Runoff, KeptRainInfo>
{
};

vtkStandardNewMacro(vtkPFRain);

vtkPFRain::vtkPFRain()
  : Cached(std::make_unique<Cache>())
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
}

vtkPFRain::~vtkPFRain() = default;

void vtkPFRain::SetPrecipitationBounds(double x0, double x1, double y0, double y1)
{
  const double b[4] = { x0, x1, y0, y1 };
  for (int k = 0; k < 4; ++k)
  {
    this->Set(this->PrecipitationBoundsValue[k], b[k]);
  }
}

void vtkPFRain::SetCells(int nx, int ny)
{
  this->Set(this->Rain.cells[0], nx);
  this->Set(this->Rain.cells[1], ny);
}

void vtkPFRain::SetImpactResolution(int nx, int ny)
{
  this->Set(this->ImpactResolution[0], nx);
  this->Set(this->ImpactResolution[1], ny);
}

void vtkPFRain::SetWindVelocity(double x, double y)
{
  this->Set(this->Rain.wind[0], x);
  this->Set(this->Rain.wind[1], y);
}

void vtkPFRain::SetPressureSolver(int solver)
{
  const parafluid::sph::SolverEntry* entry = parafluid::sph::solverForPropertyValue(solver);
  if (!entry)
  {
    vtkErrorMacro(<< "PressureSolver = " << solver << " is not a solver; kept "
                  << parafluid::sph::solverEntry(this->Water.sph.pressureSolver).label);
    return;
  }
  this->Set(this->Water.sph.pressureSolver, entry->type);
}

void vtkPFRain::SetBackend(int backend)
{
  if (parafluid::vtk::isChoice(this, "Backend", backend, { "Automatic", "CPU", "CUDA" },
                               static_cast<int>(this->Water.backend)))
  {
    this->Set(this->Water.backend, static_cast<parafluid::sph::Backend>(backend));
  }
}

void vtkPFRain::SetWallFriction(int friction)
{
  if (parafluid::vtk::isChoice(this, "WallFriction", friction,
                               { "Free-slip", "No-slip (viscous)", "Turbulent (law of the wall)" },
                               static_cast<int>(this->Water.sph.wallFriction)))
  {
    this->Set(this->Water.sph.wallFriction, static_cast<parafluid::sph::WallFriction>(friction));
  }
}

void vtkPFRain::ReportError(const std::string& message)
{
  // The cores' messages may name the filter already.
  const bool named = message.rfind("Rain: ", 0) == 0;
  vtkErrorMacro(<< (named ? "" : "Rain: ") << message);
}

int vtkPFRain::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkPFRain::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const double interval =
    this->OutputInterval > 0.0 && std::isfinite(this->OutputInterval) ? this->OutputInterval : 1.0;
  for (int port = 0; port < 3; ++port)
  {
    parafluid::vtk::setOutputTimes(outputVector->GetInformationObject(port), 0.0, interval,
                                   std::clamp(this->NumberOfOutputs, 0, 100000));
  }
  return 1;
}

int vtkPFRain::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole terrain on every process (only process 0 simulates).
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  return 1;
}

std::shared_ptr<const HeightField> vtkPFRain::ReadGround(vtkDataObject* input)
{
  try
  {
    if (auto* image = vtkImageData::SafeDownCast(input))
    {
      parafluid::vtk::HeightImage heights;
      std::string problem;
      if (!parafluid::vtk::readHeightImage(image, "", heights, problem))
      {
        this->ReportError("Terrain: " + problem);
        return nullptr;
      }
      const auto bad =
        std::find_if(heights.heights.begin(), heights.heights.end(), [](float h) { return !std::isfinite(h); });
      if (bad != heights.heights.end())
      {
        this->ReportError("Terrain: the height image's '" + heights.arrayName + "' is not finite at sample " +
                          std::to_string(bad - heights.heights.begin()) +
                          " (fill no-data with Terrain From Image first)");
        return nullptr;
      }
      if (!this->GroundFits(static_cast<double>(heights.nx) * heights.ny, "the Terrain image's samples"))
      {
        return nullptr;
      }
      return std::make_shared<HeightField>(std::move(heights.heights), heights.nx, heights.ny, heights.origin[0],
                                           heights.origin[1], heights.spacing[0], heights.spacing[1], 0.0);
    }
    auto* surface = vtkPolyData::SafeDownCast(input);
    if (!surface || surface->GetNumberOfPolys() == 0)
    {
      this->ReportError("Terrain: give a 2-D height image or a surface with polygons (got " +
                        std::string(input ? input->GetClassName() : "nothing") + " without polygons)");
      return nullptr;
    }
    if (this->ImpactResolution[0] < 2 || this->ImpactResolution[1] < 2 || this->ImpactResolution[0] > 8192 ||
        this->ImpactResolution[1] > 8192)
    {
      this->ReportError("ImpactResolution must be from 2 to 8192 nodes per side");
      return nullptr;
    }
    if (!this->GroundFits(static_cast<double>(this->ImpactResolution[0]) * this->ImpactResolution[1],
                          "ImpactResolution"))
    {
      return nullptr;
    }
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(surface);
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    vtkPolyData* mesh = triangles->GetOutput();
    std::vector<float> storage;
    const float* xyz = parafluid::vtk::positionsAsFloat(mesh, storage);
    std::vector<float> points(xyz, xyz + 3 * mesh->GetNumberOfPoints());
    for (float v : points)
    {
      if (!std::isfinite(v))
      {
        this->ReportError("Terrain: the surface has NaN or infinite point coordinates");
        return nullptr;
      }
    }
    std::vector<std::uint32_t> indices;
    vtkCellArray* polys = mesh->GetPolys();
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
    {
      if (count == 3)
      {
        indices.insert(indices.end(), { static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
                                        static_cast<std::uint32_t>(ids[2]) });
      }
    }
    return std::make_shared<HeightField>(
      HeightField::fromTriangles(points, indices, this->ImpactResolution[0], this->ImpactResolution[1], 0.0));
  }
  catch (const std::exception& e)
  {
    this->ReportError(std::string("Terrain: ") + parafluid::vtk::exceptionText(e));
    return nullptr;
  }
}

bool vtkPFRain::GroundFits(double nodes, const char* property)
{
  // Measured: the height field 8 bytes a node, and with runoff 130 (the water levels, the SPH's
  // boundary from the ground and their work arrays; 2048^2 nodes took 530 MB more than 256^2).
  const double bytes = nodes * (this->SimulateRunoff ? 130.0 : 8.0);
  char what[200];
  std::snprintf(what, sizeof(what), "the ground of %.0f nodes (%s)%s", nodes, property,
                this->SimulateRunoff ? " and its runoff" : "");
  const std::string memory = parafluid::checkMemoryBudget(bytes, what);
  if (!memory.empty())
  {
    this->ReportError(memory + "; lower " + property);
    return false;
  }
  return true;
}

bool vtkPFRain::Resolve(const HeightField& ground, parafluid::rain::RainParameters& rain)
{
  rain = this->Rain;
  double b[4];
  ground.bounds(b);
  const bool automaticArea =
    std::all_of(this->PrecipitationBoundsValue, this->PrecipitationBoundsValue + 4, [](double v) { return v == 0.0; });
  for (int k = 0; k < 4; ++k)
  {
    rain.bounds[k] = automaticArea ? b[k] : this->PrecipitationBoundsValue[k];
  }
  const auto& z = ground.elevation();
  const auto [lowest, highest] = std::minmax_element(z.begin(), z.end());
  const double relief = *highest - *lowest;
  rain.height = this->PrecipitationHeight != 0.0 ? this->PrecipitationHeight : *highest + std::max(relief, 5.0);
  // The water's SPH parameters' ranges are their declarations' (SPHParameterTable.h); CFLNumber 0
  // is the automatic choice for the solver.
  const std::string water = parafluid::sph::checkParameters(
    this->Water.sph,
    { "KinematicViscosity", "SurfaceTension", "BoundaryDamping", "CFLNumber", "SoundSpeed", "DensityTolerance" },
    { "CFLNumber" });
  const std::string runoff = parafluid::checkDeclared(parafluid::rain::runoffParameterTable(), this->Water);
  parafluid::vtk::ParameterCheck check;
  check.inRange("Seed", this->SeedValue, 0, 2147483647)
    .inRange("MaxParticles", this->MaxParticlesValue, 1, 2147483647)
    .inRange("NumberOfOutputs", this->NumberOfOutputs, 0, 100000)
    .inRange("ImpactResolution", this->ImpactResolution[0], 2, 8192)
    .inRange("ImpactResolution", this->ImpactResolution[1], 2, 8192)
    .inRange("ExposureTime", this->ExposureTime, 0.0, 10.0, "s")
    .inRange("SplashLifetime", this->SplashLifetime, 0.0, 10.0, "s")
    .inRange("OutputInterval", this->OutputInterval, 1e-6, 1e5, "s")
    .require(runoff.empty(), runoff)
    .require(water.empty(), water);
  if (!check.ok())
  {
    this->ReportError(check.problem());
    return false;
  }
  rain.seed = static_cast<std::uint64_t>(this->SeedValue);
  this->Water.maxParticles = static_cast<std::size_t>(this->MaxParticlesValue);
  const std::string problem = rain.validate();
  if (!problem.empty())
  {
    this->ReportError(problem);
    return false;
  }
  return true;
}

int vtkPFRain::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* drops = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* water = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* splashes = vtkPolyData::GetData(outputVector, 2);
  if (parafluid::vtk::processIndex() != 0)
  {
    return 1; // process 0 simulates the whole shower
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const double interval = this->OutputInterval;
  if (!(interval > 0.0) || !std::isfinite(interval))
  {
    this->ReportError("OutputInterval must be a positive number of seconds");
    return 0;
  }
  if (this->NumberOfOutputs < 0 || this->NumberOfOutputs > 100000)
  {
    this->ReportError("NumberOfOutputs must be from 0 to 100000 (got " + std::to_string(this->NumberOfOutputs) + ")");
    return 0;
  }
  const std::optional<long long> requested =
    parafluid::vtk::requestedOutput(outInfo, 0.0, interval, this->NumberOfOutputs);
  if (!requested)
  {
    this->ReportError(parafluid::vtk::notATimeError("Rain"));
    return 0;
  }
  const long long target = *requested;
  const double t = static_cast<double>(target) * interval;

  vtkDataObject* input = vtkDataObject::GetData(inputVector[0]);
  Cache& cache = *this->Cached;
  const std::vector<vtkDataObject*> outputs = { drops, water, splashes };
  cache.follow({ input ? input->GetMTime() : 0, this->GetMTime() });
  if (const KeptRainInfo* kept = this->SimulateRunoff ? cache.restore(target, outputs) : nullptr)
  {
    this->DropCount = kept->drops;
    this->FallenVolume = kept->fallen;
    this->WaterVolume = kept->water;
    this->InfiltratedVolume = kept->infiltrated;
    for (vtkPolyData* output : { drops, water, splashes })
    {
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
    }
    return 1;
  }
  const std::shared_ptr<const HeightField> ground = this->ReadGround(input);
  if (!ground)
  {
    return 0;
  }
  parafluid::rain::RainParameters rain;
  if (!this->Resolve(*ground, rain))
  {
    return 0;
  }
  try
  {
    const RainField* field = nullptr;
    std::optional<RainField> stateless;
    if (this->SimulateRunoff)
    {
      if (!cache.canContinueTo(target))
      {
        cache.dropRun();
        cache.start(std::make_unique<Runoff>(rain, this->Water, ground));
      }
      Runoff& runoff = *cache.simulation();
      // Drop steps to the requested time, at a nominal 0.1 ms a step and 20 ns a drop on a 2-core
      // machine (the SPH's share is measured as it runs).
      const double span = t - runoff.time();
      const double dropSteps = std::ceil(span / this->Water.rainStep);
      parafluid::vtk::LongWork work(this, "Rain",
                                    { dropSteps, 1e-4 + 2e-8 * static_cast<double>(runoff.rain().dropCount()),
                                      "drop steps (of RainTimeStep to the requested time)", "the requested time" });
      runoff.advance(span, [&work, dropSteps](double fraction) { return work.advance(fraction * dropSteps); });
      if (work.aborted())
      {
        cache.dropRun();
        return 1;
      }
      cache.reached(target);
      field = &runoff.rain();
    }
    else
    {
      cache.reset();
      stateless.emplace(rain, ground);
      field = &*stateless;
    }
    const Runoff* runoff = this->SimulateRunoff ? cache.simulation() : nullptr;
    const std::vector<float>* levels = runoff ? &runoff->waterLevels() : nullptr;
    const std::string memory = parafluid::checkMemoryBudget(60.0 * static_cast<double>(field->dropCount()),
                                                            "drawing " + std::to_string(field->dropCount()) + " drops");
    if (!memory.empty())
    {
      this->ReportError(memory);
      return 0;
    }
    this->WriteDrops(*field, levels, t, drops);
    this->WriteWater(t, water);
    this->WriteSplashes(*field, levels, t, splashes);
    this->FallenVolume = runoff ? runoff->fallenVolume() : 0.0;
    this->WaterVolume = runoff ? static_cast<double>(runoff->particleCount()) * runoff->particleVolume() : 0.0;
    this->InfiltratedVolume = runoff ? runoff->infiltratedVolume() : 0.0;
  }
  catch (const std::exception& e)
  {
    cache.dropRun();
    this->ReportError(parafluid::vtk::exceptionText(e));
    return 0;
  }
  for (vtkPolyData* output : { drops, water, splashes })
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
  }
  if (this->SimulateRunoff)
  {
    cache.keep(target, outputs, { this->DropCount, this->FallenVolume, this->WaterVolume, this->InfiltratedVolume });
  }
  return 1;
}

void vtkPFRain::WriteDrops(const RainField& rain, const std::vector<float>* water, double t, vtkPolyData* output)
{
  const std::size_t n = rain.dropCount();
  std::vector<float> position(3 * n), velocity(3 * n);
  std::vector<std::uint8_t> inAir(n);
  rain.evaluate(t, water, position.data(), velocity.data(), inAir.data());
  const auto& diameters = rain.diameters();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (inAir[i])
    {
      std::copy_n(&position[3 * i], 3, &position[3 * kept]);
      std::copy_n(&velocity[3 * i], 3, &velocity[3 * kept]);
      ++kept;
    }
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(kept));
  std::copy_n(position.data(), 3 * kept, static_cast<float*>(points->GetVoidPointer(0)));
  output->SetPoints(points);
  auto velocities = vtkSmartPointer<vtkFloatArray>::New();
  velocities->SetName(contract::Velocity);
  velocities->SetNumberOfComponents(3);
  velocities->SetNumberOfTuples(static_cast<vtkIdType>(kept));
  std::copy_n(velocity.data(), 3 * kept, velocities->GetPointer(0));
  auto diameter = vtkSmartPointer<vtkFloatArray>::New();
  diameter->SetName("diameter");
  diameter->SetNumberOfTuples(static_cast<vtkIdType>(kept));
  auto streak = vtkSmartPointer<vtkFloatArray>::New();
  streak->SetName("streak_length");
  streak->SetNumberOfTuples(static_cast<vtkIdType>(kept));
  for (std::size_t i = 0, k = 0; i < n; ++i)
  {
    if (inAir[i])
    {
      diameter->SetValue(static_cast<vtkIdType>(k), diameters[i]);
      const float* v = &velocity[3 * k];
      streak->SetValue(static_cast<vtkIdType>(k),
                       static_cast<float>(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * this->ExposureTime));
      ++k;
    }
  }
  output->GetPointData()->AddArray(velocities);
  output->GetPointData()->SetActiveVectors(contract::Velocity);
  output->GetPointData()->AddArray(diameter);
  output->GetPointData()->AddArray(streak);
  parafluid::vtk::setOneVertexPerPoint(output, static_cast<vtkIdType>(kept));
  this->DropCount = static_cast<vtkIdType>(kept);
}

void vtkPFRain::WriteWater(double t, vtkPolyData* output)
{
  const Runoff* runoff = this->SimulateRunoff ? this->Cached->simulation() : nullptr;
  const parafluid::sph::Simulation* sph = runoff ? runoff->water() : nullptr;
  vtkFieldData* fd = output->GetFieldData();
  if (sph)
  {
    parafluid::vtk::ParticleOutputArrays extra;
    parafluid::vtk::writeParticleState(sph->hostState(), extra, output);
    const auto& p = sph->parameters();
    const double d = runoff->parameters().particleSpacing, h = p.smoothingLength, rho0 = p.restDensity,
                 mass = p.particleMass;
    const double bounds[6] = { p.domainBounds[0], p.domainBounds[1], p.domainBounds[2],
                               p.domainBounds[3], p.domainBounds[4], p.domainBounds[5] };
    parafluid::vtk::setFieldValue(fd, contract::ParticleSpacing, &d, 1);
    parafluid::vtk::setFieldValue(fd, contract::SmoothingLength, &h, 1);
    parafluid::vtk::setFieldValue(fd, contract::RestDensity, &rho0, 1);
    parafluid::vtk::setFieldValue(fd, contract::ParticleMass, &mass, 1);
    parafluid::vtk::setFieldValue(fd, contract::DomainBounds, bounds, 6);
  }
  else
  {
    // No water yet: an empty particle set that still names the contract's arrays.
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToFloat();
    output->SetPoints(points);
    output->GetPointData()->AddArray(parafluid::vtk::floatArray(contract::Velocity, 3, {}));
    output->GetPointData()->AddArray(parafluid::vtk::floatArray(contract::Density, 1, {}));
    parafluid::vtk::setOneVertexPerPoint(output, 0);
    const double d = this->Water.particleSpacing;
    parafluid::vtk::setFieldValue(fd, contract::ParticleSpacing, &d, 1);
  }
  parafluid::vtk::setFieldValue(fd, contract::Time, &t, 1);
}

void vtkPFRain::WriteSplashes(const RainField& rain, const std::vector<float>* water, double t, vtkPolyData* output)
{
  std::vector<Impact> impacts;
  if (this->SplashLifetime > 0.0)
  {
    rain.recentImpacts(t, this->SplashLifetime, water, impacts);
  }
  const auto n = static_cast<vtkIdType>(impacts.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  auto age = vtkSmartPointer<vtkFloatArray>::New();
  age->SetName("age");
  age->SetNumberOfTuples(n);
  auto normal = vtkSmartPointer<vtkFloatArray>::New();
  normal->SetName("normal");
  normal->SetNumberOfComponents(3);
  normal->SetNumberOfTuples(n);
  auto slope = vtkSmartPointer<vtkFloatArray>::New();
  slope->SetName("slope");
  slope->SetNumberOfTuples(n);
  auto angle = vtkSmartPointer<vtkFloatArray>::New();
  angle->SetName("impact_angle");
  angle->SetNumberOfTuples(n);
  auto onWater = vtkSmartPointer<vtkUnsignedCharArray>::New();
  onWater->SetName("on_water");
  onWater->SetNumberOfTuples(n);
  const HeightField& ground = rain.ground();
  const double step = 0.5 * ground.spacing();
  double bounds[4];
  ground.bounds(bounds);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Impact& impact = impacts[static_cast<std::size_t>(i)];
    points->SetPoint(i, impact.position);
    age->SetValue(i, static_cast<float>(t - impact.time));
    double nrm[3] = { 0.0, 0.0, 1.0 };
    if (!impact.onWater)
    {
      // The ground's normal from differences of the bilinear surface, kept inside the grid (beyond
      // it the height is held constant, which would flatten the slope at the edges).
      const double x = impact.position[0], y = impact.position[1];
      const double x0 = std::max(x - step, bounds[0]), x1 = std::min(x + step, bounds[1]);
      const double y0 = std::max(y - step, bounds[2]), y1 = std::min(y + step, bounds[3]);
      const double gx = x1 > x0 ? (ground.heightAt(x1, y) - ground.heightAt(x0, y)) / (x1 - x0) : 0.0;
      const double gy = y1 > y0 ? (ground.heightAt(x, y1) - ground.heightAt(x, y0)) / (y1 - y0) : 0.0;
      const double len = std::sqrt(gx * gx + gy * gy + 1.0);
      nrm[0] = -gx / len, nrm[1] = -gy / len, nrm[2] = 1.0 / len;
    }
    normal->SetTuple(i, nrm);
    slope->SetValue(i, static_cast<float>(std::acos(std::clamp(nrm[2], -1.0, 1.0)) * 180.0 / 3.14159265358979));
    const double v[3] = { impact.velocity[0], impact.velocity[1], impact.velocity[2] };
    const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double cosine = speed > 0.0 ? -(v[0] * nrm[0] + v[1] * nrm[1] + v[2] * nrm[2]) / speed : 1.0;
    angle->SetValue(i, static_cast<float>(std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979));
    onWater->SetValue(i, impact.onWater ? 1 : 0);
  }
  output->SetPoints(points);
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ age, normal, slope, angle, onWater })
  {
    output->GetPointData()->AddArray(a);
  }
  output->GetPointData()->SetActiveScalars("age");
  parafluid::vtk::setOneVertexPerPoint(output, n);
}

void vtkPFRain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RainfallRate: " << this->Rain.rainfallRate << " mm/h\n";
  os << indent << "OutputInterval: " << this->OutputInterval << "\n";
}
