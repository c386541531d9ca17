#include "FluidShadePass.h"

#include "FluidLighting.h"
#include "FluidLightingFS.h"
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
#include <string>

namespace parafluid
{
FluidShadePass::FluidShadePass() = default;
FluidShadePass::~FluidShadePass() = default;

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
  environment = chooseFluidEnvironment(renderer, environment);
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = environment ? this->CubeMap : this->Background;
  const std::string body = std::string(FluidLightingFS) + FluidShadeFS;
  vtkShaderProgram* shade = readyScreenQuad(quad, frame, body.c_str(), environment ? "#define FLUID_CUBEMAP\n" : "");
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
  shade->SetUniformf("silhouetteRadius", s.SmoothSilhouettes ? static_cast<float>(frame.MaxRadius) : 0.0f);

  setFluidLighting(shade, renderer, environment);
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
