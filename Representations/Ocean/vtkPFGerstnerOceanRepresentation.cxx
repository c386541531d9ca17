#include "vtkPFGerstnerOceanRepresentation.h"
#include "GuardedRequest.h"
#include "parafluid/common/MathConstants.h"

#include "GerstnerOceanShading.h"
#include "GerstnerOceanWaves.h"
#include "OceanExposure.h"
#include "OceanTextures.h"
#include "ParticleArrays.h"

#include "parafluid/ocean/Bathymetry.h"
#include "parafluid/ocean/GerstnerOcean.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPVLODActor.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkTexture.h"
#include "vtkUniforms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

using parafluid::kPi;

namespace
{
constexpr int kMaxGpuWaves = 16;  // in deep or uniform water
constexpr int kMaxFloorWaves = 8; // over a bathymetry (one phase texture each)
}

struct vtkPFGerstnerOceanRepresentation::Internals
{
  std::unique_ptr<parafluid::ocean::GerstnerOcean> Model;
  std::string ModelKey;  // parameters and data the model was built from
  std::string ShaderKey; // defines the shaders were built with
  bool HasFloor = false;
  bool HasCubeMap = false;
  std::string CubeMapKey;
  vtkSmartPointer<vtkTexture> Ripples;
  vtkSmartPointer<vtkTexture> CubeMap;
  // Decoding ranges of the fixed-point data textures: floor (lowest, span); per wave, for phase,
  // wavenumber and phase derivative across: (lowest, span) each.
  double FloorRange[2] = { 0.0, 1.0 };
  std::vector<double> PhaseRanges;
  double EnvironmentMean[3] = { 0.0, 0.0, 0.0 };
};

vtkStandardNewMacro(vtkPFGerstnerOceanRepresentation);

vtkPFGerstnerOceanRepresentation::vtkPFGerstnerOceanRepresentation()
  : Internal(new Internals)
{
  // The displacement needs true coordinates in the shader, and a decimated LOD would move
  // differently from the full surface.
  for (vtkMapper* mapper : { this->Mapper, this->LODMapper })
  {
    if (auto* gl = vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
    {
      gl->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    }
  }
  this->SetSuppressLOD(true);
  this->Internal->Ripples = parafluid::vtk::makeRippleTexture();
  this->Property->SetTexture("oceanRipples", this->Internal->Ripples);
}

vtkPFGerstnerOceanRepresentation::~vtkPFGerstnerOceanRepresentation() = default;

void vtkPFGerstnerOceanRepresentation::SetWave(int index, double amplitude, double wavelength, double direction,
                                               double steepness, double phase)
{
  const double values[5] = { amplitude, wavelength, direction, steepness, phase };
  if (this->Sea.setWave(index, values))
  {
    this->Modified();
  }
}

void vtkPFGerstnerOceanRepresentation::RemoveAllWaves()
{
  if (!this->Sea.waves.empty())
  {
    this->Sea.waves.clear();
    this->Modified();
  }
}

void vtkPFGerstnerOceanRepresentation::SetBathymetryArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->BathymetryArray)
  {
    this->BathymetryArray = value;
    this->Modified();
  }
}

void vtkPFGerstnerOceanRepresentation::SetEnvironmentImage(int face, const char* file)
{
  if (face >= 0 && face < 6)
  {
    this->EnvironmentImages[face] = file ? file : "";
    this->Modified();
  }
}

int vtkPFGerstnerOceanRepresentation::ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
                                                         vtkInformation* outInfo)
{
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  if (result && request == vtkPVView::REQUEST_UPDATE())
  {
    this->ReportDisplacedBounds(inInfo);
  }
  if (result && request == vtkPVView::REQUEST_RENDER())
  {
    vtkDataObject* delivered = nullptr;
    if (vtkAlgorithmOutput* port = vtkPVRenderView::GetPieceProducer(inInfo, this, 0))
    {
      delivered = port->GetProducer()->GetOutputDataObject(port->GetIndex());
    }
    this->UpdateModel(delivered);
    this->UpdateShaders();
    auto* view = vtkPVView::SafeDownCast(this->GetView());
    this->UpdateUniforms(view ? view->GetViewTime() : 0.0);
  }
  return result;
}

void vtkPFGerstnerOceanRepresentation::ReportDisplacedBounds(vtkInformation* inInfo)
{
  // The view resets the camera and sets its clipping range from these bounds: the flat input's
  // would cut off waves higher than the plane is deep (a metre-high sea on ParaView's 1 m plane
  // drew nothing). Grow them by the largest displacement any point can reach.
  double bounds[6];
  if (!vtkGeometryRepresentation::GetBounds(this->GetRenderedDataObject(0), bounds, nullptr))
  {
    return;
  }
  const parafluid::ocean::OceanParameters p = this->Sea.parameters();
  double horizontal = 0.0, vertical = 0.0;
  parafluid::ocean::displacementBound(p, !this->BathymetryArray.empty(), horizontal, vertical);
  const double grow[3] = { horizontal, horizontal, vertical };
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] -= grow[i];
    bounds[2 * i + 1] += grow[i];
  }
  bounds[4] = std::min(bounds[4], this->Sea.seaLevel - vertical);
  bounds[5] = std::max(bounds[5], this->Sea.seaLevel + vertical);
  vtkNew<vtkMatrix4x4> matrix;
  this->Actor->GetMatrix(matrix);
  vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, matrix);

  // Waves much longer than the surface is wide make it tilt as a whole: say what to change.
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& wave : p.waves)
  {
    shortest = std::min(shortest, wave.wavelength);
  }
  const double across = std::max(bounds[1] - bounds[0] - 2.0 * horizontal, bounds[3] - bounds[2] - 2.0 * horizontal);
  std::ostringstream key;
  key << across << ' ' << shortest;
  if (std::isfinite(shortest) && across < 0.5 * shortest && key.str() != this->SizeWarningKey)
  {
    vtkWarningMacro("Gerstner Ocean: the surface is " << across << " m across but the shortest wave is " << shortest
                                                      << " m long, so the sea shows as a tilting sheet; draw it on a "
                                                         "plane several wavelengths wide (e.g. Plane with Point1 and "
                                                         "Point2 "
                                                      << 4.0 * shortest
                                                      << " m from the Origin, and enough Resolution), or choose "
                                                         "shorter Waves.");
  }
  this->SizeWarningKey = key.str();
}

void vtkPFGerstnerOceanRepresentation::UpdateModel(vtkDataObject* delivered)
{
  using namespace parafluid::ocean;
  vtkPolyData* surface = parafluid::vtk::firstPolyData(delivered);
  vtkDataArray* elevation = surface && !this->BathymetryArray.empty()
                              ? surface->GetPointData()->GetArray(this->BathymetryArray.c_str())
                              : nullptr;
  std::ostringstream key;
  key << this->Sea.key() << ' ' << this->BathymetryArray << ' ' << (elevation ? elevation->GetMTime() : 0) << ' '
      << (surface ? surface->GetMTime() : 0);
  if (key.str() == this->Internal->ModelKey && this->Internal->Model)
  {
    return;
  }
  this->Internal->ModelKey = key.str();
  this->LastError.clear();

  OceanParameters p = this->Sea.parameters();

  std::shared_ptr<Bathymetry> floor;
  double region[4] = { 0, 1, 0, 1 };
  if (!this->BathymetryArray.empty())
  {
    if (!elevation)
    {
      this->LastError = "BathymetryArray '" + this->BathymetryArray + "' is not a point array of the input";
    }
    else
    {
      // The input surface with each point lifted to its floor elevation is the terrain.
      std::vector<float> points(3 * static_cast<std::size_t>(surface->GetNumberOfPoints()));
      for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
      {
        double x[3];
        surface->GetPoint(i, x);
        points[3 * i] = static_cast<float>(x[0]);
        points[3 * i + 1] = static_cast<float>(x[1]);
        points[3 * i + 2] = static_cast<float>(elevation->GetComponent(i, 0));
      }
      std::vector<std::uint32_t> triangles;
      vtkCellArray* polys = surface->GetPolys();
      vtkIdType count;
      const vtkIdType* ids;
      for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
      {
        for (vtkIdType k = 1; k + 1 < count; ++k) // fan: the input is a flat, convex-celled surface
        {
          triangles.insert(triangles.end(), { static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[k]),
                                              static_cast<std::uint32_t>(ids[k + 1]) });
        }
      }
      try
      {
        floor = std::make_shared<Bathymetry>(Bathymetry::fromTriangles(
          points, triangles, this->Sea.bathymetryResolution, this->Sea.bathymetryResolution, this->Sea.seaLevel));
        floor->bounds(region);
      }
      catch (const std::exception& e)
      {
        this->LastError = parafluid::vtk::exceptionText(e);
      }
    }
  }
  const std::size_t limit = floor ? kMaxFloorWaves : kMaxGpuWaves;
  if (p.waves.size() > limit)
  {
    this->LastError =
      "the GPU draws the first " + std::to_string(limit) + " of " + std::to_string(p.waves.size()) + " waves";
    p.waves.resize(limit);
  }
  try
  {
    this->Internal->Model = std::make_unique<GerstnerOcean>(p, floor, floor ? region : nullptr);
  }
  catch (const std::exception& e)
  {
    this->LastError = parafluid::vtk::exceptionText(e);
    p.waves.clear();
    floor.reset();
    this->Internal->Model = std::make_unique<GerstnerOcean>(p);
  }
  if (!this->LastError.empty())
  {
    vtkWarningMacro("Gerstner Ocean: " << this->LastError);
  }

  // Float textures for the floor and the phase fields (read with texelFetch, so exact).
  this->Internal->HasFloor = static_cast<bool>(floor);
  if (floor)
  {
    const std::vector<float>& e = floor->elevation();
    const std::vector<double> elevation(e.begin(), e.end());
    std::vector<double> range;
    this->Property->SetTexture("oceanFloorTex", parafluid::vtk::makeFixedPointTexture(elevation.data(), floor->nodesX(),
                                                                                      floor->nodesY(), 1, range));
    this->Internal->FloorRange[0] = range[0];
    this->Internal->FloorRange[1] = range[1];
    const auto& fields = this->Internal->Model->phaseFields();
    this->Internal->PhaseRanges.assign(6 * kMaxFloorWaves, 0.0);
    for (std::size_t w = 0; w < static_cast<std::size_t>(kMaxFloorWaves); ++w)
    {
      const std::string name = "oceanPhase" + std::to_string(w);
      std::vector<double> samples;
      int ns = 1, nt = 1;
      if (w < fields.size())
      {
        ns = fields[w].samplesAlong(), nt = fields[w].samplesAcross();
        samples.resize(3 * static_cast<std::size_t>(ns) * nt);
        for (std::size_t k = 0; k < static_cast<std::size_t>(ns) * nt; ++k)
        {
          samples[3 * k] = fields[w].phases()[k];
          samples[3 * k + 1] = fields[w].wavenumbers()[k];
          samples[3 * k + 2] = fields[w].phasesAcross()[k];
        }
      }
      else
      {
        samples.assign(3, 0.0); // unused slot: the sampler still needs a texture
      }
      this->Property->SetTexture(name.c_str(), parafluid::vtk::makeFixedPointTexture(samples.data(), ns, nt, 3, range));
      std::copy(range.begin(), range.end(), this->Internal->PhaseRanges.begin() + 6 * w);
    }
  }
  else
  {
    this->Property->RemoveTexture("oceanFloorTex");
    for (int w = 0; w < kMaxFloorWaves; ++w)
    {
      this->Property->RemoveTexture(("oceanPhase" + std::to_string(w)).c_str());
    }
  }

  // Environment cube map: all six images or none.
  std::string cubeKey;
  int given = 0;
  for (const std::string& f : this->EnvironmentImages)
  {
    cubeKey += f + "\n";
    given += f.empty() ? 0 : 1;
  }
  if (cubeKey != this->Internal->CubeMapKey)
  {
    this->Internal->CubeMapKey = cubeKey;
    this->Internal->CubeMap = nullptr;
    if (given == 6)
    {
      std::array<std::string, 6> files;
      std::copy(this->EnvironmentImages, this->EnvironmentImages + 6, files.begin());
      std::string error;
      this->Internal->CubeMap = parafluid::vtk::loadCubeMap(files, error, this->Internal->EnvironmentMean);
      if (!this->Internal->CubeMap)
      {
        vtkErrorMacro("Gerstner Ocean: " << error);
      }
    }
    else if (given > 0)
    {
      vtkWarningMacro("Gerstner Ocean: EnvironmentImages needs all six faces; using the procedural sky");
    }
    if (this->Internal->CubeMap)
    {
      this->Property->SetTexture("oceanEnvironment", this->Internal->CubeMap);
    }
    else
    {
      this->Property->RemoveTexture("oceanEnvironment");
    }
  }
  this->Internal->HasCubeMap = static_cast<bool>(this->Internal->CubeMap);
}

void vtkPFGerstnerOceanRepresentation::UpdateShaders()
{
  std::string defines;
  if (this->Internal->HasFloor)
  {
    defines += "#define OCEAN_FLOOR\n";
  }
  if (this->Internal->HasCubeMap)
  {
    defines += "#define OCEAN_CUBEMAP\n";
  }
  if (!this->Internal->HasFloor && !(this->Sea.waterDepth > 0.0))
  {
    // Deep water compiles to a single pass over the waves: software renderers run both sides of
    // a branch, so the general path would cost even where it is not taken.
    defines += "#define OCEAN_DEEP\n";
  }
  const std::string key = "built\n" + defines;
  if (key == this->Internal->ShaderKey)
  {
    return;
  }
  this->Internal->ShaderKey = key;
  vtkShaderProperty* shaders = this->Actor->GetShaderProperty();
  shaders->ClearAllShaderReplacements();
  std::string vertexSamplers;
  if (this->Internal->HasFloor)
  {
    vertexSamplers += "uniform sampler2D oceanFloorTex;\n";
    for (int w = 0; w < kMaxFloorWaves; ++w)
    {
      vertexSamplers += "uniform sampler2D oceanPhase" + std::to_string(w) + ";\n";
    }
  }
  shaders->AddVertexShaderReplacement(
    "//VTK::PositionVC::Dec", true,
    "//VTK::PositionVC::Dec\n" + defines + vertexSamplers + GerstnerOceanWaves +
      "out vec3 oceanRestVSOutput;\nout vec3 oceanWorldVSOutput;\nout vec3 oceanEyeVSOutput;\n"
      "out vec3 oceanDxVSOutput;\nout vec3 oceanDyVSOutput;\nout vec2 oceanFoamDepthVSOutput;\n",
    false);
  shaders->AddVertexShaderReplacement(
    "//VTK::PositionVC::Impl", true,
    "  vec3 oceanOffset, oceanDx, oceanDy;\n"
    "  float oceanJ, oceanFoam, oceanH;\n"
    // VTK may shift and scale the coordinates it uploads (vertexMC); the camera's view-to-world
    // matrix, set every render, recovers world coordinates, in which the waves are defined.
    // The shift and scale are per axis, so world = MC * scale + shift with scale the diagonal of
    // VCWC * MCVC: cheaper per vertex than forming and inverting that matrix.
    "  vec4 oceanRest = oceanVCWC * (MCVCMatrix * vertexMC);\n"
    "  vec3 oceanScale = vec3(dot(vec4(oceanVCWC[0][0], oceanVCWC[1][0], oceanVCWC[2][0], oceanVCWC[3][0]), "
    "MCVCMatrix[0]),\n"
    "    dot(vec4(oceanVCWC[0][1], oceanVCWC[1][1], oceanVCWC[2][1], oceanVCWC[3][1]), MCVCMatrix[1]),\n"
    "    dot(vec4(oceanVCWC[0][2], oceanVCWC[1][2], oceanVCWC[2][2], oceanVCWC[3][2]), MCVCMatrix[2]));\n"
    "  oceanEvaluate(oceanRest.xy, oceanOffset, oceanDx, oceanDy, oceanJ, oceanFoam, oceanH);\n"
    "  vec4 oceanVertex = vertexMC + vec4(oceanOffset / oceanScale, 0.0);\n"
    "  oceanRestVSOutput = oceanRest.xyz;\n"
    "  oceanWorldVSOutput = oceanRest.xyz + oceanOffset;\n"
    "  oceanEyeVSOutput = (oceanVCWC * vec4(0.0, 0.0, 0.0, 1.0)).xyz;\n"
    "  oceanDxVSOutput = oceanDx;\n"
    "  oceanDyVSOutput = oceanDy;\n"
    "  oceanFoamDepthVSOutput = vec2(oceanFoam, min(oceanH, 1.0e6));\n"
    "  vertexVCVSOutput = MCVCMatrix * oceanVertex;\n"
    "  gl_Position = MCDCMatrix * oceanVertex;\n",
    false);
  // Fragment: the waves' derivatives come interpolated from the vertices (evaluating eight waves
  // per pixel cost 3x the frame time in software rendering, for no visible gain at a few vertices
  // per metre); the normal is built from them per pixel. Declarations go after the texture
  // samplers VTK declares (TMap).
  shaders->AddFragmentShaderReplacement(
    "//VTK::PositionVC::Dec", true,
    "//VTK::PositionVC::Dec\n" + defines +
      "in vec3 oceanRestVSOutput;\nin vec3 oceanWorldVSOutput;\nin vec3 oceanEyeVSOutput;\n"
      "in vec3 oceanDxVSOutput;\nin vec3 oceanDyVSOutput;\nin vec2 oceanFoamDepthVSOutput;\n",
    false);
  shaders->AddFragmentShaderReplacement("//VTK::Clip::Dec", true,
                                        std::string(GerstnerOceanShading) + "//VTK::Clip::Dec\n", false);
  shaders->AddFragmentShaderReplacement(
    "//VTK::Light::Impl", true,
    "  vec3 oceanDx = oceanDxVSOutput, oceanDy = oceanDyVSOutput;\n"
    "  float oceanFoam = oceanFoamDepthVSOutput.x, oceanH = oceanFoamDepthVSOutput.y;\n"
    "  vec3 oceanColor = oceanShadingMode == 1 ? oceanSolidColor\n"
    "    : oceanShadingMode == 2 ? 0.5 + 0.5 * normalize(cross(vec3(1.0 + oceanDx.x, oceanDx.y, oceanDx.z), "
    "vec3(oceanDy.x, 1.0 + oceanDy.y, oceanDy.z)))\n"
    "    : oceanShade(oceanWorldVSOutput, oceanEyeVSOutput, oceanRestVSOutput.xy, oceanDx, oceanDy, oceanFoam, "
    "oceanH);\n"
    "  gl_FragData[0] = vec4(oceanColor, opacity);\n",
    false);
  // Textures are the shader's data, not colours to multiply in.
  shaders->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, "", false);
}

bool vtkPFGerstnerOceanRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    // After ParaView's own StartEvent observers (priority 0), which give a server's processes the
    // client's camera: ParaView asks for the render before that.
    this->CameraObserver = renderView->GetRenderer()->AddObserver(
      vtkCommand::StartEvent, this, &vtkPFGerstnerOceanRepresentation::UpdateViewToWorld, -1.0f);
  }
  return this->Superclass::AddToView(view);
}

bool vtkPFGerstnerOceanRepresentation::RemoveFromView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->RemoveObserver(this->CameraObserver);
  }
  return this->Superclass::RemoveFromView(view);
}

void vtkPFGerstnerOceanRepresentation::UpdateViewToWorld()
{
  vtkNew<vtkMatrix4x4> viewToWorld;
  if (auto* view = vtkPVRenderView::SafeDownCast(this->GetView()))
  {
    vtkMatrix4x4::Invert(view->GetActiveCamera()->GetModelViewTransformMatrix(), viewToWorld);
  }
  viewToWorld->Transpose(); // vtkUniforms uploads row by row; GLSL reads columns
  this->Actor->GetShaderProperty()->GetVertexCustomUniforms()->SetUniformMatrix("oceanVCWC", viewToWorld);
}

void vtkPFGerstnerOceanRepresentation::UpdateUniforms(double time)
{
  const auto* model = this->Internal->Model.get();
  if (!model)
  {
    return;
  }
  const auto& waves = model->effectiveWaves();
  const int count = static_cast<int>(std::min<std::size_t>(waves.size(), kMaxGpuWaves));
  float amplitude[kMaxGpuWaves] = {}, steepness[kMaxGpuWaves] = {}, phaseNow[kMaxGpuWaves] = {};
  float lean[kMaxGpuWaves] = {}, dirX[kMaxGpuWaves] = {}, dirY[kMaxGpuWaves] = {}, uniformK[kMaxGpuWaves] = {};
  for (int i = 0; i < count; ++i)
  {
    amplitude[i] = static_cast<float>(waves[i].amplitude);
    steepness[i] = static_cast<float>(waves[i].steepness);
    // phase - omega t, reduced in double precision so float keeps full accuracy on the GPU.
    phaseNow[i] = static_cast<float>(std::remainder(waves[i].phase - model->angularFrequencies()[i] * time, 2.0 * kPi));
    lean[i] = static_cast<float>(model->leans()[i]);
    dirX[i] = static_cast<float>(model->directionX(i));
    dirY[i] = static_cast<float>(model->directionY(i));
    uniformK[i] = static_cast<float>(model->uniformWavenumbers()[i]);
  }
  const double sunElevation = this->SunElevation * kPi / 180.0, sunAzimuth = this->SunAzimuth * kPi / 180.0;
  const float sun[3] = { static_cast<float>(std::cos(sunElevation) * std::cos(sunAzimuth)),
                         static_cast<float>(std::cos(sunElevation) * std::sin(sunAzimuth)),
                         static_cast<float>(std::sin(sunElevation)) };
  // Auto exposure: the mean luminance of the water as this camera sees it (flat sea, same shading
  // model) mapped to 18 % grey by the tone curve 1 - exp(-L e).
  this->EffectiveExposure = this->Exposure;
  auto* renderView = vtkPVRenderView::SafeDownCast(this->GetView());
  if (this->AutoExposure && renderView)
  {
    parafluid::vtk::OceanExposureScene scene;
    vtkCamera* camera = renderView->GetActiveCamera();
    camera->GetPosition(scene.eye);
    camera->GetFocalPoint(scene.focal);
    camera->GetViewUp(scene.up);
    scene.viewAngle = camera->GetViewAngle();
    double aspect[2] = { 1.0, 1.0 };
    renderView->GetRenderer()->GetAspect(aspect);
    scene.aspect = aspect[0] / std::max(aspect[1], 1e-9);
    scene.seaLevel = this->Sea.seaLevel;
    for (int c = 0; c < 3; ++c)
    {
      scene.sun[c] = sun[c];
      scene.sunColor[c] = this->SunColor[c];
      scene.horizon[c] = this->HorizonColor[c];
      scene.zenith[c] = this->ZenithColor[c];
      scene.environmentMean[c] = this->Internal->EnvironmentMean[c] * this->EnvironmentScale;
      scene.deepColor[c] = this->DeepColor[c];
      scene.shallowColor[c] = this->ShallowColor[c];
    }
    scene.sunIntensity = this->SunIntensity;
    scene.shininess = this->Shininess;
    scene.hasEnvironment = this->Internal->HasCubeMap;
    scene.colorDepth = std::max(this->ColorDepth, 1e-3);
    if (const auto* floor = model->bathymetry())
    {
      scene.depth = [floor](double x, double y) { return floor->depth(x, y); };
    }
    else if (this->Sea.waterDepth > 0.0)
    {
      const double depth = this->Sea.waterDepth;
      scene.depth = [depth](double, double) { return depth; };
    }
    const double mean = parafluid::vtk::meanWaterLuminance(scene);
    if (mean > 0.0)
    {
      this->EffectiveExposure = -std::log(1.0 - 0.18) / mean;
    }
  }

  this->UpdateViewToWorld();
  for (vtkUniforms* u : { this->Actor->GetShaderProperty()->GetVertexCustomUniforms(),
                          this->Actor->GetShaderProperty()->GetFragmentCustomUniforms() })
  {
    u->SetUniformi("oceanWaveCount", count);
    u->SetUniform1fv("oceanAmplitude", kMaxGpuWaves, amplitude);
    u->SetUniform1fv("oceanSteepness", kMaxGpuWaves, steepness);
    u->SetUniform1fv("oceanPhaseNow", kMaxGpuWaves, phaseNow);
    u->SetUniform1fv("oceanLean", kMaxGpuWaves, lean);
    u->SetUniform1fv("oceanDirX", kMaxGpuWaves, dirX);
    u->SetUniform1fv("oceanDirY", kMaxGpuWaves, dirY);
    u->SetUniform1fv("oceanUniformK", kMaxGpuWaves, uniformK);
    const auto& p = model->parameters();
    u->SetUniformf("oceanDepth", std::isinf(p.depth) ? -1.0f : static_cast<float>(p.depth));
    u->SetUniformf("oceanMaxSteepness", static_cast<float>(p.maxSteepness));
    u->SetUniformf("oceanMinDepth", static_cast<float>(p.minDepth));
    u->SetUniformf("oceanBreakRatio", static_cast<float>(p.breakingDepthRatio));
    u->SetUniformf("oceanBreakStretch", static_cast<float>(p.breakingStretch));
    u->SetUniformf("oceanBreakLean", static_cast<float>(p.breakingLean));
    u->SetUniformf("oceanBreakShift", static_cast<float>(p.breakingShift));
    u->SetUniformf("oceanSeaLevel", static_cast<float>(this->Sea.seaLevel));
    if (const auto* floor = model->bathymetry())
    {
      double origin[2], spacing[2];
      floor->grid(origin, spacing);
      const float o[2] = { static_cast<float>(origin[0]), static_cast<float>(origin[1]) };
      const float s[2] = { static_cast<float>(spacing[0]), static_cast<float>(spacing[1]) };
      const float n[2] = { static_cast<float>(floor->nodesX()), static_cast<float>(floor->nodesY()) };
      u->SetUniform2f("oceanFloorOrigin", o);
      u->SetUniform2f("oceanFloorSpacing", s);
      u->SetUniform2f("oceanFloorSize", n);
      float s0[kMaxFloorWaves] = {}, t0[kMaxFloorWaves] = {}, st[kMaxFloorWaves] = {}, ns[kMaxFloorWaves] = {},
            nt[kMaxFloorWaves] = {};
      const auto& fields = model->phaseFields();
      for (std::size_t w = 0; w < fields.size() && w < static_cast<std::size_t>(kMaxFloorWaves); ++w)
      {
        double a, b, c;
        fields[w].grid(a, b, c);
        s0[w] = static_cast<float>(a), t0[w] = static_cast<float>(b), st[w] = static_cast<float>(c);
        ns[w] = static_cast<float>(fields[w].samplesAlong()), nt[w] = static_cast<float>(fields[w].samplesAcross());
      }
      u->SetUniform1fv("oceanGridS0", kMaxFloorWaves, s0);
      u->SetUniform1fv("oceanGridT0", kMaxFloorWaves, t0);
      u->SetUniform1fv("oceanGridStep", kMaxFloorWaves, st);
      u->SetUniform1fv("oceanGridNS", kMaxFloorWaves, ns);
      u->SetUniform1fv("oceanGridNT", kMaxFloorWaves, nt);
      const float floorRange[2] = { static_cast<float>(this->Internal->FloorRange[0]),
                                    static_cast<float>(this->Internal->FloorRange[1]) };
      u->SetUniform2f("oceanFloorRange", floorRange);
      const char* names[6] = { "oceanPhaseLo", "oceanPhaseSpan", "oceanKLo",
                               "oceanKSpan",   "oceanAcrossLo",  "oceanAcrossSpan" };
      for (int r = 0; r < 6; ++r)
      {
        float values[kMaxFloorWaves];
        for (int w = 0; w < kMaxFloorWaves; ++w)
        {
          values[w] = static_cast<float>(this->Internal->PhaseRanges[6 * w + r]);
        }
        u->SetUniform1fv(names[r], kMaxFloorWaves, values);
      }
    }
  }
  vtkUniforms* f = this->Actor->GetShaderProperty()->GetFragmentCustomUniforms();
  f->SetUniformi("oceanShadingMode", this->ShadingMode);
  f->SetUniform3f("oceanSolidColor", this->SolidColor);
  f->SetUniform3f("oceanDeepColor", this->DeepColor);
  f->SetUniform3f("oceanShallowColor", this->ShallowColor);
  f->SetUniformf("oceanColorDepth", static_cast<float>(std::max(this->ColorDepth, 1e-3)));
  f->SetUniform3f("oceanFoamColor", this->FoamColor);
  f->SetUniformf("oceanFoamAmount", static_cast<float>(this->FoamAmount));
  f->SetUniform3f("oceanSunDirection", sun);
  f->SetUniform3f("oceanSunColor", this->SunColor);
  f->SetUniformf("oceanSunIntensity", static_cast<float>(this->SunIntensity));
  f->SetUniformf("oceanShininess", static_cast<float>(this->Shininess));
  f->SetUniform3f("oceanHorizonColor", this->HorizonColor);
  f->SetUniform3f("oceanZenithColor", this->ZenithColor);
  f->SetUniformf("oceanEnvironmentScale", static_cast<float>(this->EnvironmentScale));
  f->SetUniformf("oceanRippleScale", static_cast<float>(std::max(this->RippleScale, 1e-3)));
  f->SetUniformf("oceanRippleStrength", static_cast<float>(this->RippleStrength));
  f->SetUniformf("oceanRippleTime", static_cast<float>(std::fmod(time * this->RippleSpeed, 1.0e4)));
  f->SetUniformf("oceanRippleFade", static_cast<float>(std::max(this->RippleFade, 1e-3)));
  f->SetUniformf("oceanExposure", static_cast<float>(this->EffectiveExposure));
}

void vtkPFGerstnerOceanRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SeaState: " << this->Sea.seaState << "\n";
  os << indent << "BathymetryArray: " << this->BathymetryArray << "\n";
  os << indent << "ShadingMode: " << this->ShadingMode << "\n";
}
