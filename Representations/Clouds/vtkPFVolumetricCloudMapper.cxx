#include "vtkPFVolumetricCloudMapper.h"

#include "CloudMarchPass.h"
#include "CloudVolumeTextures.h"
#include "GuardedRequest.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkPFVolumetricCloudMapper);

struct vtkPFVolumetricCloudMapper::Internals
{
  parafluid::CloudVolumeTextures Textures;
  parafluid::CloudMarchPass Pass;
};

vtkPFVolumetricCloudMapper::vtkPFVolumetricCloudMapper()
  : GPU(new Internals)
{
}

vtkPFVolumetricCloudMapper::~vtkPFVolumetricCloudMapper() = default;

void vtkPFVolumetricCloudMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DensityArray: " << this->DensityArray << "\n";
  os << indent << "Extinction: " << this->Extinction << "\n";
  os << indent << "Shadows: " << this->Shadows << "\n";
}

double vtkPFVolumetricCloudMapper::GetLastLightMilliseconds() const
{
  return this->GPU->Textures.LastLightMilliseconds();
}

void vtkPFVolumetricCloudMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->GPU->Textures.Release(window);
  this->GPU->Pass.Release(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

double* vtkPFVolumetricCloudMapper::GetBounds()
{
  auto* image = vtkImageData::SafeDownCast(this->GetInput());
  if (!image || image->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  image->GetBounds(this->Bounds);
  double spacing[3];
  image->GetSpacing(spacing);
  for (int axis = 0; axis < 3; ++axis)
  {
    this->Bounds[2 * axis] -= 0.5 * std::abs(spacing[axis]);
    this->Bounds[2 * axis + 1] += 0.5 * std::abs(spacing[axis]);
  }
  return this->Bounds;
}

void vtkPFVolumetricCloudMapper::ChooseLight(vtkRenderer* renderer, double direction[3], double color[3]) const
{
  if (this->LightMode == 1)
  {
    const double e = vtkMath::RadiansFromDegrees(this->SunElevation);
    const double a = vtkMath::RadiansFromDegrees(this->SunAzimuth);
    direction[0] = std::cos(e) * std::cos(a);
    direction[1] = std::cos(e) * std::sin(a);
    direction[2] = std::sin(e);
    for (int c = 0; c < 3; ++c)
    {
      color[c] = this->SunColor[c] * this->LightIntensity;
    }
    return;
  }
  // The view's key light: ParaView's light kit puts it first; otherwise a headlight.
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0)
    {
      continue;
    }
    double position[3], focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    for (int c = 0; c < 3; ++c)
    {
      direction[c] = position[c] - focal[c];
    }
    if (vtkMath::Normalize(direction) > 0.0)
    {
      double diffuse[3];
      light->GetDiffuseColor(diffuse);
      for (int c = 0; c < 3; ++c)
      {
        color[c] = diffuse[c] * light->GetIntensity() * this->LightIntensity;
      }
      return;
    }
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  for (int c = 0; c < 3; ++c)
  {
    direction[c] = position[c] - focal[c];
    color[c] = this->LightIntensity;
  }
  vtkMath::Normalize(direction);
}

namespace
{
// The optical depth of the densest voxel beyond which the light paths are read as at this depth.
constexpr double kResolvedVoxelDepth = 2.0;
} // namespace

void vtkPFVolumetricCloudMapper::Render(vtkRenderer* renderer, vtkVolume*)
{
  this->LastMarched = false;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  auto* image = vtkImageData::SafeDownCast(this->GetInput());
  if (!window || !image || image->GetNumberOfPoints() == 0)
  {
    return;
  }
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
    // errors of earlier drawing are not ours to report
  }
  parafluid::CloudMarchSettings s;
  this->ChooseLight(renderer, s.LightDirection, s.LightColor);
  vtkMTimeType key = image->GetMTime();
  std::string error;
  try
  {
    const bool shadows = this->Shadows;
    if (!this->GPU->Textures.Update(window, image, this->DensityArray.c_str(), std::max(key, this->GetMTime()),
                                    s.LightDirection, shadows, error))
    {
      if (error != this->LastError)
      {
        vtkErrorMacro("Volumetric Cloud: " << error);
        this->LastError = error;
      }
      return;
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Volumetric Cloud: " << parafluid::vtk::exceptionText(e));
    return;
  }
  this->LastError.clear();
  const parafluid::CloudVolumeTextures& textures = this->GPU->Textures;
  double spacing[3];
  image->GetSpacing(spacing);
  const double sample = std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) });
  const double* box = textures.Box();
  const double diagonal = std::sqrt((box[1] - box[0]) * (box[1] - box[0]) + (box[3] - box[2]) * (box[3] - box[2]) +
                                    (box[5] - box[4]) * (box[5] - box[4]));
  // Opacity below 1e-4 across the whole box cannot change a pixel: no march at all.
  const double faintest = 1e-4 / std::max(this->Extinction * diagonal, 1e-30);
  if (!(textures.MaxDensity() > faintest))
  {
    return;
  }
  s.Extinction = this->Extinction;
  // The densest voxel at most kResolvedVoxelDepth optical depths deep for the light.
  s.LightExtinction = std::min(this->Extinction, kResolvedVoxelDepth / (textures.MaxDensity() * sample));
  s.Albedo = this->Albedo;
  s.Anisotropy = this->Anisotropy;
  s.StepLength = this->StepSize * sample;
  s.MaxSteps = this->MaxSteps;
  s.MinTransmittance = this->MinTransmittance;
  // A block whose densest sample absorbs under 1e-4 across the block is empty.
  s.EmptyDensity = this->EmptySpaceSkipping
                     ? 1e-4 / std::max(this->Extinction * parafluid::CloudVolumeTextures::BlockSamples * sample, 1e-30)
                     : -1.0;
  std::copy(this->SkyColor, this->SkyColor + 3, s.SkyColor);
  s.Shadows = this->Shadows;
  s.Octaves = this->Octaves;
  s.Powder = this->Powder;
  s.DisplayMode = this->DisplayMode;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  s.WriteDepth = controller && controller->GetNumberOfProcesses() > 1;
  if (!this->GPU->Pass.Run(window, renderer, textures, s))
  {
    vtkErrorMacro("The volumetric cloud shader did not compile (see the messages above).");
    return;
  }
  this->LastMarched = true;
  const GLenum glError = glGetError();
  if (glError != GL_NO_ERROR)
  {
    vtkErrorMacro("OpenGL error 0x" << std::hex << glError << std::dec << " in the volumetric cloud pass.");
  }
}
