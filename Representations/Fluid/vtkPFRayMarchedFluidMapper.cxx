#include "vtkPFRayMarchedFluidMapper.h"

#include "FluidFrame.h"
#include "FluidScreenTargets.h"
#include "FluidSharedScene.h"
#include "GuardedRequest.h"
#include "RayMarchBoundsPass.h"
#include "RayMarchBuffers.h"
#include "RayMarchPass.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointSet.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

vtkStandardNewMacro(vtkPFRayMarchedFluidMapper);

/// The GPU side: the particle grid, the opaque scene's copy, the march.
struct vtkPFRayMarchedFluidMapper::Internals
{
  vtkOpenGLRenderWindow* Context = nullptr;
  parafluid::RayMarchBuffers Buffers;
  parafluid::FluidScreenTargets Targets;
  parafluid::RayMarchBoundsPass Bounds;
  parafluid::RayMarchPass Pass;

  void Release(vtkWindow* window)
  {
    this->Buffers.Release(window);
    this->Bounds.Release(window);
    this->Targets.Release(window);
    this->Pass.Release(window);
    this->Context = nullptr;
  }
};

vtkPFRayMarchedFluidMapper::vtkPFRayMarchedFluidMapper()
  : March(new Internals)
{
  this->SetDisplayMode(TransparentFluid);
}

vtkPFRayMarchedFluidMapper::~vtkPFRayMarchedFluidMapper() = default;

void vtkPFRayMarchedFluidMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParticleSpacing: " << this->ParticleSpacing << "\n";
  os << indent << "KernelRadius: " << this->KernelRadius << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "MaxSteps: " << this->MaxSteps << "\n";
  os << indent << "ResolutionScale: " << this->ResolutionScale << "\n";
  os << indent << "EmptySpaceSkipping: " << this->EmptySpaceSkipping << "\n";
  os << indent << "StartStopSplats: " << this->StartStopSplats << "\n";
  os << indent << "SeparateSplash: " << this->SeparateSplash << "\n";
}

double vtkPFRayMarchedFluidMapper::EffectiveSpacing()
{
  return this->ParticleSpacing > 0.0 ? this->ParticleSpacing : this->GetParticleRadius() / 0.6;
}

long long vtkPFRayMarchedFluidMapper::GetLastCellCount() const
{
  const int* d = this->March->Buffers.Grid().dims();
  return static_cast<long long>(d[0]) * d[1] * d[2];
}

long long vtkPFRayMarchedFluidMapper::GetLastOccupiedCellCount() const
{
  return static_cast<long long>(this->March->Buffers.Grid().occupiedCells());
}

long long vtkPFRayMarchedFluidMapper::GetLastSplashCount() const
{
  return static_cast<long long>(this->March->Buffers.Grid().splashParticles());
}

long long vtkPFRayMarchedFluidMapper::GetLastUnsplattedCount() const
{
  return static_cast<long long>(this->March->Buffers.Grid().unsplattedParticles());
}

double vtkPFRayMarchedFluidMapper::GetLastBuildMilliseconds() const
{
  return this->March->Buffers.LastBuildMilliseconds();
}

void vtkPFRayMarchedFluidMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->March->Release(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

double* vtkPFRayMarchedFluidMapper::GetBounds()
{
  auto* input = vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  input->GetBounds(this->Bounds);
  // The surface lies within the kernel's reach of the particle centres.
  const double reach = this->KernelRadius * this->EffectiveSpacing();
  for (int i = 0; i < 3; ++i)
  {
    this->Bounds[2 * i] -= reach;
    this->Bounds[2 * i + 1] += reach;
  }
  return this->Bounds;
}

void vtkPFRayMarchedFluidMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  Internals& in = *this->March;
  this->LastSpacing = 0.0;
  parafluid::FluidSharedScene shared(this->GetSharedRendering(), renderer);
  if (shared.Lends())
  {
    shared.Lend();
    return;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  auto* input = vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!window || !input || input->GetNumberOfPoints() == 0)
  {
    return;
  }
  if (in.Context && in.Context != window)
  {
    in.Release(in.Context);
  }
  in.Context = window;
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
    // errors of earlier drawing are not ours to report
  }
  const double spacing = this->EffectiveSpacing();
  vtkUnsignedCharArray* colors = this->MapParticleColors(input);
  vtkMTimeType key = std::max(input->GetMTime(), this->GetMTime());
  if (colors)
  {
    key = std::max(key, colors->GetMTime());
  }
  try
  {
    in.Buffers.Update(window, input, spacing, this->KernelRadius * spacing, this->IsoValue, colors, key);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Ray-Marched Fluid: " << parafluid::vtk::exceptionText(e));
    return;
  }
  if (in.Buffers.Grid().particleCount() == 0)
  {
    return; // no finite particle
  }
  this->LastSpacing = spacing;
  parafluid::FluidFrame frame;
  frame.Window = window;
  frame.State = window->GetState();
  frame.Renderer = renderer;
  if (!this->PlaceOnScreen(renderer, actor, frame, in.Buffers.Bounds(), this->KernelRadius * spacing, 1))
  {
    return;
  }
  const bool transparent = this->GetDisplayMode() == TransparentFluid;

  vtkOpenGLState* state = frame.State;
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglScissor savedScissor(state);
  vtkOpenGLState::ScopedglEnableDisable savedScissorTest(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
  vtkOpenGLState::ScopedglColorMask savedColorMask(state);
  vtkOpenGLState::ScopedglClearColor savedClearColor(state);

  std::fill(this->PassMilliseconds, this->PassMilliseconds + 3, 0.0);
  auto lap = std::chrono::steady_clock::now();
  auto timePass = [&](int pass)
  {
    if (this->TimePasses)
    {
      glFinish();
      const auto now = std::chrono::steady_clock::now();
      this->PassMilliseconds[pass] = std::chrono::duration<double, std::milli>(now - lap).count();
      lap = now;
    }
  };
  if (this->TimePasses)
  {
    glFinish();
    lap = std::chrono::steady_clock::now();
  }
  in.Targets.Ensure(window, frame.Size[0], frame.Size[1], 4, false, false);
  frame.Framebuffer = in.Targets.Framebuffer;
  {
    // Refracted rays can leave the fluid's rectangle: transparent fluid reads the whole viewport.
    parafluid::FluidFrame whole = frame;
    if (transparent)
    {
      whole.RectMin[0] = whole.RectMin[1] = 0;
      whole.RectMax[0] = frame.Size[0];
      whole.RectMax[1] = frame.Size[1];
    }
    in.Targets.CopyOpaqueScene(whole, transparent);
    shared.Composite(whole, in.Targets, transparent);
  }
  state->vtkglEnable(GL_SCISSOR_TEST);
  timePass(0);

  vtkTextureObject* bounds = nullptr;
  if (this->EmptySpaceSkipping && this->StartStopSplats)
  {
    const int marchSize[2] = { parafluid::RayMarchPass::MarchSize(frame, this->ResolutionScale, 0),
                               parafluid::RayMarchPass::MarchSize(frame, this->ResolutionScale, 1) };
    const double pixelScale = 1.0 / parafluid::RayMarchPass::ChooseScale(this->ResolutionScale);
    if (!in.Bounds.Run(frame, in.Buffers, in.Targets.EmptyVAO, marchSize, pixelScale, this->SeparateSplash))
    {
      vtkErrorMacro("The ray-marched fluid's splat shader did not compile (see the messages above).");
      return;
    }
    bounds = in.Bounds.Bounds();
  }
  timePass(1);

  parafluid::RayMarchSettings s;
  s.DisplayMode = std::min(this->GetDisplayMode(), static_cast<int>(Steps));
  s.StepLength = this->StepSize * spacing;
  s.MaxSteps = this->MaxSteps;
  s.Skipping = this->EmptySpaceSkipping;
  s.ResolutionScale = this->ResolutionScale;
  this->GetFluidColor(s.FluidColor);
  s.AttenuationDistance = this->GetAttenuationDistance();
  s.RefractiveIndex = this->GetRefractiveIndex();
  s.Shininess = this->GetShininess();
  s.SpecularStrength = this->GetSpecularStrength();
  s.Ambient = this->GetAmbient();
  s.ColorMix = this->GetColorMix();
  if (!in.Pass.Run(frame, in.Buffers, in.Targets.OpaqueDepth, in.Targets.OpaqueColor, bounds,
                   this->GetEnvironmentTexture(), s))
  {
    vtkErrorMacro("The ray-marched fluid shader did not compile (see the messages above).");
    return;
  }
  timePass(2);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
  {
    vtkErrorMacro("OpenGL error 0x" << std::hex << error << std::dec << " in the ray-marched fluid passes.");
  }
}
