#include "FluidShadePass.h"

#include "FluidScreenQuad.h"
#include "FluidScreenTargets.h"
#include "FluidShadeFS.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLTexture.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace parafluid
{
FluidShadePass::FluidShadePass() = default;
FluidShadePass::~FluidShadePass() = default;

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

void FluidShadePass::Run(FluidFrame& frame, FluidScreenTargets& targets, const Inputs& inputs, vtkTexture* environment,
                         const FluidShadeSettings& s)
{
  vtkOpenGLState* state = frame.State;
  vtkRenderer* renderer = frame.Renderer;
  state->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  state->vtkglScissor(frame.Origin[0] + frame.RectMin[0], frame.Origin[1] + frame.RectMin[1], frame.RectWidth(),
                      frame.RectHeight());
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  if (!environment && renderer->GetEnvironmentTexture() && renderer->GetEnvironmentTexture()->GetCubeMap())
  {
    environment = renderer->GetEnvironmentTexture();
  }
  if (environment && !environment->GetCubeMap())
  {
    environment = nullptr;
  }
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = environment ? this->CubeMap : this->Background;
  vtkShaderProgram* shade = readyScreenQuad(quad, frame, FluidShadeFS, environment ? "#define FLUID_CUBEMAP\n" : "");
  shade->SetUniformMatrix("VCDCMatrix", frame.Projection);
  shade->SetUniformi("displayMode", s.DisplayMode);
  shade->SetUniformi("toonBands", s.ToonBands);
  shade->SetUniform3f("lineColor", s.LineColor);
  shade->SetUniformf("contourSpacing", static_cast<float>(s.DepthContourSpacing * frame.MaxRadius));
  shade->SetUniform3f("fluidColor", s.FluidColor);
  shade->SetUniformf("attenuationDistance", static_cast<float>(s.AttenuationDistance));
  shade->SetUniformf("refractiveIndex", static_cast<float>(s.RefractiveIndex));
  shade->SetUniformf("refractionStrength", static_cast<float>(s.RefractionStrength));
  shade->SetUniformf("shininess", static_cast<float>(s.Shininess));
  shade->SetUniformf("specularStrength", static_cast<float>(s.SpecularStrength));
  shade->SetUniformf("ambient", static_cast<float>(s.Ambient));
  shade->SetUniformf("colorMix", static_cast<float>(s.ColorMix));
  const float depthRange[2] = { static_cast<float>(std::max(frame.Nearest, frame.NearDistance)),
                                static_cast<float>(frame.Farthest) };
  shade->SetUniform2f("depthRange", depthRange);

  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetViewTransformMatrix();
  setLights(shade, renderer, view);
  setEyeToCube(shade, renderer, environment, view);
  const double* bottom = renderer->GetBackground();
  const double* top = renderer->GetGradientBackground() ? renderer->GetBackground2() : bottom;
  shade->SetUniform3f("backgroundBottom", bottom);
  shade->SetUniform3f("backgroundTop", top);
  if (environment)
  {
    environment->Render(renderer);
    auto* gl = vtkOpenGLTexture::SafeDownCast(environment);
    if (gl && gl->GetTextureObject())
    {
      shade->SetUniformi("environment", gl->GetTextureUnit());
    }
  }
  // The targets read, bound while the pass draws.
  struct Bound
  {
    vtkTextureObject* texture;
    const char* sampler;
  };
  Bound bound[5] = {};
  int count = 0;
  bound[count++] = { targets.Depth[inputs.Depth], "depthTex" };
  if (inputs.Thickness)
  {
    bound[count++] = { targets.Thickness[0], "thicknessTex" };
  }
  if (inputs.OpaqueColor)
  {
    bound[count++] = { targets.OpaqueColor, "opaqueColor" };
  }
  if (inputs.ParticleColors)
  {
    bound[count++] = { targets.ParticleColors, "particleColorTex" };
  }
  if (inputs.Lines)
  {
    bound[count++] = { targets.Lines, "linesTex" };
  }
  for (int i = 0; i < count; ++i)
  {
    bound[i].texture->Activate();
    shade->SetUniformi(bound[i].sampler, bound[i].texture->GetTextureUnit());
  }
  if (inputs.Thickness)
  {
    const int f = targets.ThicknessFactor;
    const float toThickness[2] = { 1.0f / (f * ((frame.Size[0] + f - 1) / f)),
                                   1.0f / (f * ((frame.Size[1] + f - 1) / f)) };
    shade->SetUniform2f("thicknessScale", toThickness);
  }
  shade->SetUniformi("hasParticleColors", inputs.ParticleColors ? 1 : 0);
  quad->Render();
  ++frame.PassCount;
  for (int i = 0; i < count; ++i)
  {
    bound[i].texture->Deactivate();
  }
  if (environment)
  {
    environment->PostRender(renderer);
  }
}

void FluidShadePass::Release(vtkWindow* window)
{
  releaseScreenQuad(this->Background, window);
  releaseScreenQuad(this->CubeMap, window);
}
} // namespace parafluid
