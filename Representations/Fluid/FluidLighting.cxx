#include "FluidLighting.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLTexture.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"

namespace parafluid
{
namespace
{
/// Up to 6 lights: directions in eye space (the view matrix's rotation), colour x intensity.
void setLights(vtkShaderProgram* shade, vtkRenderer* renderer, vtkMatrix4x4* view)
{
  float directions[6][3] = {};
  float lightColors[6][3] = {};
  int count = 0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || count == 6)
    {
      continue;
    }
    double d[3] = { 0.0, 0.0, -1.0 };
    if (!light->LightTypeIsHeadlight())
    {
      double p[3], f[3], w[3];
      light->GetTransformedPosition(p);
      light->GetTransformedFocalPoint(f);
      for (int k = 0; k < 3; ++k)
      {
        w[k] = f[k] - p[k];
      }
      for (int r = 0; r < 3; ++r)
      {
        d[r] = view->GetElement(r, 0) * w[0] + view->GetElement(r, 1) * w[1] + view->GetElement(r, 2) * w[2];
      }
      vtkMath::Normalize(d);
    }
    const double* c = light->GetDiffuseColor();
    for (int k = 0; k < 3; ++k)
    {
      directions[count][k] = static_cast<float>(d[k]);
      lightColors[count][k] = static_cast<float>(c[k] * light->GetIntensity());
    }
    ++count;
  }
  shade->SetUniformi("lightCount", count);
  shade->SetUniform3fv("lightDirectionVC", 6, directions);
  shade->SetUniform3fv("lightColor", 6, lightColors);
}

/// Eye direction -> world (the inverse rotation is the transpose), then world -> the cube map's
/// frame: ParaFluid's images have +Y = world +Z; the renderer's environment says its own axes.
void setEyeToCube(vtkShaderProgram* shade, vtkRenderer* renderer, vtkTexture* environment, vtkMatrix4x4* view)
{
  double cubeAxes[3][3] = { { 1, 0, 0 }, { 0, 0, 1 }, { 0, -1, 0 } };
  if (environment && environment == renderer->GetEnvironmentTexture())
  {
    const double* up = renderer->GetEnvironmentUp();
    const double* right = renderer->GetEnvironmentRight();
    double front[3];
    vtkMath::Cross(right, up, front);
    for (int k = 0; k < 3; ++k)
    {
      cubeAxes[0][k] = right[k];
      cubeAxes[1][k] = up[k];
      cubeAxes[2][k] = front[k];
    }
  }
  // eyeToCube = cubeAxes * R^T; GLSL reads the array column-major, so store its transpose.
  float eyeToCube[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      double v = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        v += cubeAxes[r][k] * view->GetElement(c, k);
      }
      eyeToCube[c * 3 + r] = static_cast<float>(v);
    }
  }
  shade->SetUniformMatrix3x3("eyeToCube", eyeToCube);
}
} // namespace

vtkTexture* chooseFluidEnvironment(vtkRenderer* renderer, vtkTexture* mine)
{
  vtkTexture* environment = mine;
  if (!environment && renderer->GetEnvironmentTexture() && renderer->GetEnvironmentTexture()->GetCubeMap())
  {
    environment = renderer->GetEnvironmentTexture();
  }
  return environment && environment->GetCubeMap() ? environment : nullptr;
}

void setFluidLighting(vtkShaderProgram* program, vtkRenderer* renderer, vtkTexture* environment)
{
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetViewTransformMatrix();
  setLights(program, renderer, view);
  setEyeToCube(program, renderer, environment, view);
  const double* bottom = renderer->GetBackground();
  const double* top = renderer->GetGradientBackground() ? renderer->GetBackground2() : bottom;
  program->SetUniform3f("backgroundBottom", bottom);
  program->SetUniform3f("backgroundTop", top);
  if (environment)
  {
    environment->Render(renderer);
    auto* gl = vtkOpenGLTexture::SafeDownCast(environment);
    if (gl && gl->GetTextureObject())
    {
      program->SetUniformi("environment", gl->GetTextureUnit());
    }
  }
}
} // namespace parafluid
