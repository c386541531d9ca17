#include "vtkPFRainMapper.h"

#include "RainEnvironment.h"
#include "RainFrame.h"
#include "RainPointBuffer.h"
#include "RainSplashPass.h"
#include "RainStreakCpuPass.h"
#include "RainStreakPass.h"

#include "parafluid/rain/SplashSprites.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

struct vtkPFRainMapper::Internals
{
  parafluid::RainPointBuffer Points;
  parafluid::RainStreakPass Streak;
  parafluid::RainStreakCpuPass CpuStreak;
  int SoftwareRenderer = -1; // of the context, found at the first frame (-1: not yet)
  bool LastOnCpu = false;
  parafluid::RainSplashPass Splash;
  parafluid::RainEnvironment Environment;
  parafluid::SharedFrameTakeOver TakeOver;
  std::vector<float> Packed;
  int PackedKind = -1;
  vtkMTimeType PackedKey = 0;
  vtkMTimeType Uploads = 0;
};

vtkStandardNewMacro(vtkPFRainMapper);

vtkPFRainMapper::vtkPFRainMapper()
  : Internal(std::make_unique<Internals>())
{
}

vtkPFRainMapper::~vtkPFRainMapper() = default;

bool vtkPFRainMapper::GetLastDrawnOnCpu() const
{
  return this->Internal->LastOnCpu;
}

int vtkPFRainMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkPFRainMapper::SetEnvironmentImage(int face, const char* file)
{
  this->Internal->Environment.SetImage(face, file ? file : "");
  this->Modified();
}

double* vtkPFRainMapper::GetBounds()
{
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  else
  {
    input->GetBounds(this->Bounds);
  }
  return this->Bounds;
}

namespace
{
/// Streaks: (x, y, z, diameter), (vx, vy, vz, streak_length) per drop; non-finite drops are left
/// out.
void packDrops(vtkPolyData* input, std::vector<float>& packed)
{
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* diameter = pd->GetArray("diameter");
  vtkDataArray* velocity = pd->GetArray("velocity");
  vtkDataArray* streak = pd->GetArray("streak_length");
  velocity = velocity && velocity->GetNumberOfComponents() == 3 ? velocity : nullptr;
  const vtkIdType n = input->GetNumberOfPoints();
  packed.clear();
  packed.reserve(static_cast<std::size_t>(8 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], v[3] = { 0.0, 0.0, -6.0 };
    input->GetPoint(i, x);
    if (velocity)
    {
      velocity->GetTuple(i, v);
    }
    const double d = diameter ? diameter->GetComponent(i, 0) : 2e-3;
    const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double length = streak ? streak->GetComponent(i, 0) : speed / 60.0;
    const double all[8] = { x[0], x[1], x[2], d, v[0], v[1], v[2], length };
    if (!std::all_of(all, all + 8, [](double value) { return std::isfinite(value); }) || d <= 0.0)
    {
      continue;
    }
    packed.insert(packed.end(), all, all + 8);
  }
}

/// Splashes: (x, y, z, age), (nx, ny, nz, sequence + impact angle / 180).
void packSplashes(vtkPolyData* input, std::vector<float>& packed)
{
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* age = pd->GetArray("age");
  vtkDataArray* normal = pd->GetArray("normal");
  vtkDataArray* slope = pd->GetArray("slope");
  vtkDataArray* angle = pd->GetArray("impact_angle");
  vtkDataArray* water = pd->GetArray("on_water");
  normal = normal && normal->GetNumberOfComponents() == 3 ? normal : nullptr;
  const vtkIdType n = input->GetNumberOfPoints();
  packed.clear();
  packed.reserve(static_cast<std::size_t>(8 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], nrm[3] = { 0.0, 0.0, 1.0 };
    input->GetPoint(i, x);
    if (normal)
    {
      normal->GetTuple(i, nrm);
    }
    const double a = age ? age->GetComponent(i, 0) : 0.0;
    const auto kind = parafluid::rain::splashKindForSlope(slope ? slope->GetComponent(i, 0) : 0.0,
                                                          water && water->GetComponent(i, 0) != 0.0);
    const double impact = std::clamp(angle ? angle->GetComponent(i, 0) : 0.0, 0.0, 179.0);
    const double all[8] = { x[0], x[1], x[2], a, nrm[0], nrm[1], nrm[2], static_cast<int>(kind) + impact / 180.0 };
    if (!std::all_of(all, all + 8, [](double value) { return std::isfinite(value); }))
    {
      continue;
    }
    packed.insert(packed.end(), all, all + 8);
  }
}
} // namespace

void vtkPFRainMapper::Render(vtkRenderer* renderer, vtkActor*)
{
  Internals& in = *this->Internal;
  if (!in.TakeOver.Run(this->Sharing, renderer))
  {
    return; // process 0 draws this frame's rain over the whole scene
  }
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!input || !window)
  {
    return;
  }
  const vtkMTimeType key = std::max(input->GetMTime(), this->GetMTime());
  // Packed and uploaded only when the data, a setting or the kind changed.
  if (in.PackedKind != this->Kind || key != in.PackedKey)
  {
    if (this->Kind == Streaks)
    {
      packDrops(input, in.Packed);
    }
    else
    {
      packSplashes(input, in.Packed);
    }
    in.Points.Update(window, in.Packed, ++in.Uploads);
    in.PackedKind = this->Kind;
    in.PackedKey = key;
  }
  if (in.Packed.empty())
  {
    return;
  }

  parafluid::RainFrame frame;
  frame.Window = window;
  frame.State = window->GetState();
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  frame.Viewport[0] = static_cast<float>(size[0]);
  frame.Viewport[1] = static_cast<float>(size[1]);
  frame.Origin[0] = origin[0];
  frame.Origin[1] = origin[1];
  auto* camera = static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera());
  vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  camera->GetKeyMatrices(renderer, wcvc, normals, vcdc, wcdc); // stored transposed, ready to upload
  frame.WorldToView = wcvc;
  frame.ViewToClip = vcdc;
  double eye[3];
  camera->GetPosition(eye);
  for (int k = 0; k < 3; ++k)
  {
    frame.Eye[k] = static_cast<float>(eye[k]);
  }
  frame.Environment = in.Environment.Coefficients(renderer, this->ViewBackground[0], this->ViewBackground[1]);
  bool ok = true;
  if (this->Kind == Streaks)
  {
    parafluid::RainStreakPass::Settings settings;
    settings.RefractiveIndex = this->RefractiveIndex;
    settings.Brightness = this->Brightness;
    settings.Opacity = this->Opacity;
    settings.FogDistance = this->FogDistance;
    settings.WidthScale = this->WidthScale;
    settings.MaxStreakArea =
      parafluid::rain::streakAreaLimit(static_cast<double>(size[0]) * size[1], in.Packed.size() / 8);
    settings.RadianceOnly = this->DisplayMode == 1;
    if (in.SoftwareRenderer < 0)
    {
      in.SoftwareRenderer = parafluid::RainStreakCpuPass::SoftwareRenderer() ? 1 : 0;
    }
    // The CPU draws blended streaks only (the opaque Radiance display writes depth: the GPU's).
    const bool cpu = !settings.RadianceOnly && (this->Rasteriser == CpuRasteriser ||
                                                (this->Rasteriser == AutomaticRasteriser && in.SoftwareRenderer == 1));
    in.LastOnCpu = false;
    if (cpu)
    {
      const std::vector<float>& radiance = in.Streak.Radiance(frame, settings.RefractiveIndex);
      const parafluid::rain::RadianceTable table{ radiance.data(), parafluid::RainStreakPass::kRadianceColumns,
                                                  parafluid::RainStreakPass::kTransferRows };
      parafluid::rain::StreakLook look;
      look.widthScale = static_cast<float>(settings.WidthScale);
      look.maxArea = static_cast<float>(settings.MaxStreakArea);
      look.brightness = static_cast<float>(settings.Brightness);
      look.opacity = static_cast<float>(settings.Opacity);
      look.fogDistance = static_cast<float>(settings.FogDistance);
      in.LastOnCpu = in.CpuStreak.Run(frame, in.Packed, table, look);
    }
    // On the GPU, or when the CPU could not (a multisampled framebuffer's depth cannot be read).
    ok = in.LastOnCpu || in.Streak.Run(frame, in.Points, settings);
  }
  else
  {
    parafluid::RainSplashPass::Settings settings;
    settings.SplashSize = this->SplashSize;
    settings.Lifetime = this->SplashLifetime;
    settings.Brightness = this->Brightness;
    settings.Opacity = this->Opacity;
    in.Environment.Average(settings.Ambient);
    ok = in.Splash.Run(frame, in.Points, settings);
  }
  if (!ok)
  {
    vtkErrorMacro("The rain shader did not compile (see the messages above).");
  }
}

void vtkPFRainMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Points.Release(window);
  this->Internal->Streak.Release(window);
  this->Internal->CpuStreak.Release(window);
  this->Internal->SoftwareRenderer = -1;
  this->Internal->Splash.Release(window);
  this->Internal->TakeOver.Release(window);
  this->Internal->PackedKind = -1;
}
