#include "RayMarchPass.h"

#include "FluidLighting.h"
#include "FluidLightingFS.h"
#include "FluidScreenTargets.h"
#include "RayMarchBoundsPass.h"
#include "RayMarchBuffers.h"
#include "RayMarchFS.h"
#include "RayMarchUpsampleFS.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cmath>
#include <string>

namespace parafluid
{
namespace
{
enum Variant
{
  Transparent = 1,
  ParticleColors = 2,
  LowResolution = 4,
  CubeMap = 8,
  SplatBounds = 16
};

std::string defines(int variant)
{
  std::string d;
  d += (variant & Transparent) ? "#define TRANSPARENT_FLUID\n" : "";
  d += (variant & ParticleColors) ? "#define PARTICLE_COLORS\n" : "";
  d += (variant & LowResolution) ? "#define LOW_RESOLUTION\n" : "";
  d += (variant & CubeMap) ? "#define FLUID_CUBEMAP\n" : "";
  d += (variant & SplatBounds)
         ? "#define SPLAT_BOUNDS\n#define BOUNDS_PIXELS " + std::to_string(RayMarchBoundsPass::BoundsPixels) + "\n"
         : "";
  return d;
}

/// Binds texture objects to units for one draw and unbinds them after.
class BoundTextures
{
public:
  explicit BoundTextures(vtkShaderProgram* program)
    : Program(program)
  {
  }
  void Bind(vtkTextureObject* texture, const char* sampler)
  {
    texture->Activate();
    this->Program->SetUniformi(sampler, texture->GetTextureUnit());
    this->Textures[this->Count++] = texture;
  }
  ~BoundTextures()
  {
    for (int i = 0; i < this->Count; ++i)
    {
      this->Textures[i]->Deactivate();
    }
  }

private:
  vtkShaderProgram* Program;
  vtkTextureObject* Textures[8] = {};
  int Count = 0;
};
} // namespace

RayMarchPass::RayMarchPass() = default;
RayMarchPass::~RayMarchPass() = default;

void RayMarchPass::EnsureLowResolution(FluidFrame& frame, int width, int height)
{
  if (!this->LowColor)
  {
    this->LowColor = makeScreenTexture(frame.Window);
    this->LowColor->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    this->LowDepth = makeScreenTexture(frame.Window);
    this->LowDepth->SetInternalFormat(GL_R32F);
    this->LowDepth->SetFormat(GL_RED);
    this->LowDepth->Allocate2D(width, height, 1, VTK_FLOAT);
  }
  else if (static_cast<int>(this->LowColor->GetWidth()) != width ||
           static_cast<int>(this->LowColor->GetHeight()) != height)
  {
    this->LowColor->Resize(width, height);
    this->LowDepth->Resize(width, height);
  }
}

int RayMarchPass::MarchSize(const FluidFrame& frame, double resolutionScale, int axis)
{
  return static_cast<int>(std::ceil(frame.Size[axis] * ChooseScale(resolutionScale)));
}

double RayMarchPass::ChooseScale(double resolutionScale)
{
  return resolutionScale >= 1.0 ? 1.0 : (resolutionScale >= 0.5 ? 0.5 : 0.25);
}

bool RayMarchPass::Run(FluidFrame& frame, const RayMarchBuffers& buffers, vtkTextureObject* opaqueDepth,
                       vtkTextureObject* opaqueColor, vtkTextureObject* bounds, vtkTexture* environment,
                       const RayMarchSettings& s)
{
  vtkOpenGLState* state = frame.State;
  vtkRenderer* renderer = frame.Renderer;
  environment = chooseFluidEnvironment(renderer, environment);
  const double scale = ChooseScale(s.ResolutionScale);
  const bool low = scale < 1.0;
  const bool transparent = s.DisplayMode == 1;
  const int variant = (transparent ? Transparent : 0) | (buffers.Colors() ? ParticleColors : 0) |
                      (low ? LowResolution : 0) | (environment ? CubeMap : 0) | (bounds ? SplatBounds : 0);
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->March[variant];
  const std::string body = std::string(FluidLightingFS) + RayMarchFS;
  vtkShaderProgram* march = readyScreenQuad(quad, frame, body.c_str(), defines(variant).c_str());
  if (!march || !march->GetCompiled())
  {
    return false;
  }
  const surface::DensityCellGrid& grid = buffers.Grid();
  // The key matrices are transposed: the inverse of the key model-view is the key form of the
  // inverse, uploaded the same way.
  vtkNew<vtkMatrix4x4> eyeToModel;
  vtkMatrix4x4::Invert(frame.ModelView, eyeToModel);
  march->SetUniformMatrix("eyeToModel", eyeToModel);
  march->SetUniformMatrix("modelToEye", frame.ModelView);
  march->SetUniformMatrix("VCDCMatrix", frame.Projection);
  const float depthCoefficients[2] = { static_cast<float>(frame.Projection->GetElement(2, 2)),
                                       static_cast<float>(frame.Projection->GetElement(3, 2)) };
  march->SetUniform2f("depthCoefficients", depthCoefficients);
  const float origin[3] = { static_cast<float>(grid.origin()[0]), static_cast<float>(grid.origin()[1]),
                            static_cast<float>(grid.origin()[2]) };
  march->SetUniform3f("gridOrigin", origin);
  march->SetUniformf("cellSize", static_cast<float>(grid.cellSize()));
  // (vtkShaderProgram has no ivec3 setter: int[3] arrays.)
  march->SetUniform1iv("gridDimsV", 3, grid.dims());
  march->SetUniform1iv("blockDimsV", 3, grid.blockDims());
  march->SetUniformi("blockCells", surface::DensityCellGrid::BlockCells);
  const double r = grid.kernelRadius();
  march->SetUniformf("kernelRadius", static_cast<float>(r));
  // phi = scale sum (r^2 - s^2)^3 = scale r^6 sum (1 - s^2 / r^2)^3
  march->SetUniformf("kernelScale", static_cast<float>(grid.kernelScale() * std::pow(r, 6)));
  march->SetUniformf("isoValue", static_cast<float>(grid.isoValue()));
  march->SetUniformf("stepLength", static_cast<float>(s.StepLength));
  march->SetUniformi("maxSteps", s.MaxSteps);
  march->SetUniformi("skipping", s.Skipping ? 1 : 0);
  march->SetUniformi("displayMode", s.DisplayMode);
  march->SetUniform3f("fluidColor", s.FluidColor);
  march->SetUniformf("attenuationDistance", static_cast<float>(s.AttenuationDistance));
  march->SetUniformf("refractiveIndex", static_cast<float>(s.RefractiveIndex));
  march->SetUniformf("shininess", static_cast<float>(s.Shininess));
  march->SetUniformf("specularStrength", static_cast<float>(s.SpecularStrength));
  march->SetUniformf("ambient", static_cast<float>(s.Ambient));
  march->SetUniformf("colorMix", static_cast<float>(s.ColorMix));
  setFluidLighting(march, renderer, environment);
  const int lowSize[2] = { MarchSize(frame, scale, 0), MarchSize(frame, scale, 1) };
  march->SetUniform2i("marchSize", low ? lowSize : frame.Size);
  march->SetUniformf("pixelScale", static_cast<float>(1.0 / scale));
  {
    BoundTextures bound(march);
    bound.Bind(buffers.Particles(), "particles");
    bound.Bind(buffers.CellStart(), "cellStart");
    bound.Bind(buffers.Blocks(), "blockOccupied");
    bound.Bind(opaqueDepth, "opaqueDepthTex");
    if (bounds)
    {
      bound.Bind(bounds, "boundsTex");
    }
    if (buffers.Colors())
    {
      bound.Bind(buffers.Colors(), "particleColors");
    }
    if (transparent)
    {
      bound.Bind(opaqueColor, "opaqueColor");
    }
    if (!low)
    {
      state->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
      state->vtkglScissor(frame.Origin[0] + frame.RectMin[0], frame.Origin[1] + frame.RectMin[1], frame.RectWidth(),
                          frame.RectHeight());
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_LEQUAL);
      state->vtkglDepthMask(GL_TRUE);
      state->vtkglDisable(GL_BLEND);
      quad->Render();
      ++frame.PassCount;
    }
    else
    {
      this->EnsureLowResolution(frame, lowSize[0], lowSize[1]);
      state->PushFramebufferBindings();
      frame.Framebuffer->Bind();
      frame.Framebuffer->AddColorAttachment(0, this->LowColor);
      frame.Framebuffer->AddColorAttachment(1, this->LowDepth);
      frame.Framebuffer->ActivateDrawBuffers(2);
      state->vtkglViewport(0, 0, lowSize[0], lowSize[1]);
      const int x0 = static_cast<int>(std::floor(frame.RectMin[0] * scale));
      const int y0 = static_cast<int>(std::floor(frame.RectMin[1] * scale));
      const int x1 = static_cast<int>(std::ceil(frame.RectMax[0] * scale));
      const int y1 = static_cast<int>(std::ceil(frame.RectMax[1] * scale));
      state->vtkglScissor(x0, y0, x1 - x0, y1 - y0);
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglDisable(GL_BLEND);
      state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
      quad->Render();
      ++frame.PassCount;
      frame.Framebuffer->RemoveColorAttachment(1);
      frame.Framebuffer->RemoveColorAttachment(0);
      frame.Framebuffer->ActivateDrawBuffers(1);
      state->PopFramebufferBindings();
    }
  }
  if (environment)
  {
    environment->PostRender(renderer);
  }
  if (!low)
  {
    return true;
  }
  // Up to the viewport, into the view.
  vtkShaderProgram* up = readyScreenQuad(this->Upsample, frame, RayMarchUpsampleFS);
  if (!up || !up->GetCompiled())
  {
    return false;
  }
  up->SetUniform2i("lowSize", lowSize);
  up->SetUniformf("pixelScale", static_cast<float>(1.0 / scale));
  up->SetUniformf("depthTolerance", 1e-3f);
  BoundTextures bound(up);
  bound.Bind(this->LowColor, "lowColor");
  bound.Bind(this->LowDepth, "lowDepth");
  bound.Bind(opaqueDepth, "opaqueDepthTex");
  state->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  state->vtkglScissor(frame.Origin[0] + frame.RectMin[0], frame.Origin[1] + frame.RectMin[1], frame.RectWidth(),
                      frame.RectHeight());
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  this->Upsample->Render();
  ++frame.PassCount;
  return true;
}

void RayMarchPass::Release(vtkWindow* window)
{
  for (auto& entry : this->March)
  {
    releaseScreenQuad(entry.second, window);
  }
  this->March.clear();
  releaseScreenQuad(this->Upsample, window);
  for (vtkTextureObject* t : { this->LowColor.Get(), this->LowDepth.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->LowColor = this->LowDepth = nullptr;
}
} // namespace parafluid
