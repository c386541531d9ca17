#include "vtkPFScreenSpaceFluidMapper.h"

#include "FluidDepthSmoothingPass.h"
#include "FluidFootprint.h"
#include "FluidFrame.h"
#include "FluidParticleBuffers.h"
#include "FluidScreenTargets.h"
#include "FluidShadePass.h"
#include "FluidSharedScene.h"
#include "FluidSplatPass.h"
#include "FluidThicknessBlurPass.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPFScreenSpaceFluidMapper);

/// The GPU side: the particles, the screen targets, and one object per pass.
struct vtkPFScreenSpaceFluidMapper::Internals
{
  vtkOpenGLRenderWindow* Context = nullptr;
  parafluid::FluidParticleBuffers Particles;
  parafluid::FluidScreenTargets Targets;
  parafluid::FluidSplatPass Splats;
  parafluid::FluidThicknessBlurPass ThicknessBlur;
  parafluid::FluidDepthSmoothingPass Smoothing;
  parafluid::FluidShadePass Shade;
  vtkSmartPointer<vtkTexture> Environment;
  vtkNew<vtkMatrix4x4> ModelView; // model -> view of the frame being drawn (key matrix, transposed)
  float MaxPointSize = 0.0f;      // the context's largest point sprite, pixels (0: not asked yet)

  void Release(vtkWindow* window)
  {
    this->Particles.Release(window);
    this->Targets.Release(window);
    this->Splats.Release(window);
    this->ThicknessBlur.Release(window);
    this->Smoothing.Release(window);
    this->Shade.Release(window);
    if (this->Environment)
    {
      this->Environment->ReleaseGraphicsResources(window);
    }
    this->Context = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkPFScreenSpaceFluidMapper::vtkPFScreenSpaceFluidMapper()
  : Internal(new Internals)
{
}

vtkPFScreenSpaceFluidMapper::~vtkPFScreenSpaceFluidMapper() = default;

void vtkPFScreenSpaceFluidMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParticleRadius: " << this->ParticleRadius << "\n";
  os << indent << "RadiusArray: " << this->RadiusArray << "\n";
  os << indent << "SmoothingMethod: " << this->SmoothingMethod << "\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "DisplayMode: " << this->DisplayMode << "\n";
}

int vtkPFScreenSpaceFluidMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkPFScreenSpaceFluidMapper::SetRadiusArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->RadiusArray)
  {
    this->RadiusArray = value;
    this->Modified();
  }
}

void vtkPFScreenSpaceFluidMapper::SetEnvironmentTexture(vtkTexture* texture)
{
  if (this->Internal->Environment != texture)
  {
    this->Internal->Environment = texture;
    this->Modified();
  }
}

void vtkPFScreenSpaceFluidMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ReleaseStyle(window);
  this->Internal->Release(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

double* vtkPFScreenSpaceFluidMapper::GetBounds()
{
  auto* input = vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  input->GetBounds(this->Bounds);
  // The spheres reach a radius past the centres.
  double radius = this->ParticleRadius;
  if (!this->RadiusArray.empty())
  {
    if (vtkDataArray* radii = input->GetPointData()->GetArray(this->RadiusArray.c_str()))
    {
      radius = std::max(std::abs(radii->GetRange(0)[0]), std::abs(radii->GetRange(0)[1]));
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    this->Bounds[2 * i] -= radius;
    this->Bounds[2 * i + 1] += radius;
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
bool vtkPFScreenSpaceFluidMapper::UploadParticles(vtkPointSet* input, vtkOpenGLRenderWindow* window)
{
  Internals& in = *this->Internal;
  vtkUnsignedCharArray* colors = this->MapParticleColors(input);
  vtkMTimeType key = std::max(input->GetMTime(), this->GetMTime());
  if (colors)
  {
    key = std::max(key, colors->GetMTime());
  }
  vtkDataArray* radii =
    this->RadiusArray.empty() ? nullptr : input->GetPointData()->GetArray(this->RadiusArray.c_str());
  in.Particles.Update(window, input, radii, this->ParticleRadius, colors, key);
  if (in.Particles.MaxRadius() <= 0.0)
  {
    return false; // nothing finite to draw
  }
  this->PrepareStyle(input, colors, window, key);
  return true;
}

vtkUnsignedCharArray* vtkPFScreenSpaceFluidMapper::MapParticleColors(vtkPointSet* input)
{
  int cellFlag = 0;
  vtkUnsignedCharArray* colors = this->ScalarVisibility ? this->MapScalars(input, 1.0, cellFlag) : nullptr;
  if (colors && (cellFlag != 0 || colors->GetNumberOfTuples() != input->GetNumberOfPoints()))
  {
    colors = nullptr; // cell colours have no particle to sit on
  }
  return colors;
}

vtkTexture* vtkPFScreenSpaceFluidMapper::GetEnvironmentTexture() const
{
  return this->Internal->Environment;
}

bool vtkPFScreenSpaceFluidMapper::PlaceOnScreen(vtkRenderer* renderer, vtkActor* actor, parafluid::FluidFrame& frame,
                                                const double bounds[6], double reach, int margin)
{
  Internals& in = *this->Internal;
  renderer->GetTiledSizeAndOrigin(&frame.Size[0], &frame.Size[1], &frame.Origin[0], &frame.Origin[1]);
  if (frame.Size[0] <= 0 || frame.Size[1] <= 0)
  {
    return false;
  }
  // The key matrices are stored transposed, ready for SetUniformMatrix.
  auto* camera = static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera());
  vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  camera->GetKeyMatrices(renderer, wcvc, normals, vcdc, wcdc);
  in.ModelView->DeepCopy(wcvc);
  if (actor && !actor->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc = nullptr;
    vtkMatrix3x3* actorNormals = nullptr;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, actorNormals);
    vtkMatrix4x4::Multiply4x4(mcwc, wcvc, in.ModelView);
  }
  frame.ModelView = in.ModelView;
  frame.Projection = vcdc;
  frame.Parallel = camera->GetParallelProjection() != 0;
  frame.NearDistance = camera->GetClippingRange()[0];
  const int row = frame.Parallel ? 3 : 2;
  frame.ProjectionCoefficients[0] = static_cast<float>(vcdc->GetElement(0, 0));
  frame.ProjectionCoefficients[1] = static_cast<float>(vcdc->GetElement(1, 1));
  frame.ProjectionCoefficients[2] = static_cast<float>(vcdc->GetElement(row, 0));
  frame.ProjectionCoefficients[3] = static_cast<float>(vcdc->GetElement(row, 1));
  if (in.MaxPointSize <= 0.0f)
  {
    GLfloat range[2] = { 0.0f, 0.0f };
    glGetFloatv(GL_POINT_SIZE_RANGE, range);
    in.MaxPointSize = std::max(1.0f, range[1]);
  }
  parafluid::FluidFootprintQuery query;
  std::copy(bounds, bounds + 6, query.Bounds);
  query.MaxRadius = reach;
  for (int k = 0; k < 16; ++k)
  {
    query.ModelView[k] = frame.ModelView->GetElement(k / 4, k % 4);
    query.Projection[k] = vcdc->GetElement(k / 4, k % 4);
  }
  query.Parallel = frame.Parallel;
  query.NearDistance = frame.NearDistance;
  query.Size[0] = frame.Size[0];
  query.Size[1] = frame.Size[1];
  query.Margin = margin;
  query.MaxPointSize = in.MaxPointSize;
  const parafluid::FluidFootprint footprint = parafluid::computeFluidFootprint(query);
  if (!footprint.Visible)
  {
    return false;
  }
  frame.RectMin[0] = footprint.Rect[0];
  frame.RectMin[1] = footprint.Rect[1];
  frame.RectMax[0] = footprint.Rect[2];
  frame.RectMax[1] = footprint.Rect[3];
  frame.Nearest = footprint.Nearest;
  frame.Farthest = footprint.Farthest;
  frame.MaxRadius = reach;
  frame.PointSprites = footprint.PointSprites;
  this->LastUsedPointSprites = footprint.PointSprites;
  std::copy(footprint.Rect, footprint.Rect + 4, this->LastScreenRect);
  return true;
}

int vtkPFScreenSpaceFluidMapper::ChooseThicknessFactor(const parafluid::FluidFrame& frame) const
{
  // Thickness is blurred anyway, so it is splatted at reduced resolution: half, or a quarter when
  // particles are small on screen (radius under 8 pixels at the fluid's middle depth), where
  // the fill of a million overlapping splats would dominate the frame. Particles under 1.5
  // thickness pixels deposit their volume on the 4 nearest pixels instead of sampling their chord
  // (FluidSplatVS.glsl), so the thickness stays the fluid's volume per unit area at any size.
  const double middle = frame.Parallel ? 1.0 : std::max(0.5 * (frame.Nearest + frame.Farthest), 1e-12);
  const double radiusPixels = frame.MaxRadius * frame.Projection->GetElement(1, 1) * 0.5 * frame.Size[1] / middle;
  return radiusPixels < 8.0 ? 4 : 2;
}

void vtkPFScreenSpaceFluidMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  Internals& in = *this->Internal;
  this->LastPassCount = 0;
  this->LastUsedPointSprites = false;
  this->LastThicknessFactor = 0;
  std::fill(this->LastScreenRect, this->LastScreenRect + 4, 0);
  parafluid::FluidSharedScene shared(this->Sharing, renderer);
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
    this->ReleaseStyle(in.Context);
    in.Release(in.Context);
  }
  in.Context = window;
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
    // errors of earlier drawing are not ours to report
  }
  parafluid::FluidFrame frame;
  frame.Window = window;
  frame.State = window->GetState();
  frame.Renderer = renderer;
  if (!this->UploadParticles(input, window) ||
      !this->PlaceOnScreen(renderer, actor, frame, in.Particles.Bounds(), in.Particles.MaxRadius(),
                           this->MaxFilterRadius + 2))
  {
    return;
  }
  // Passes a setting does not need are not run.
  const int mode = this->DisplayMode;
  const bool thickness = mode == TransparentFluid || mode == Thickness;
  const bool refraction = mode == TransparentFluid;
  const bool smooth = mode != ParticleDepth && this->SmoothingIterations > 0;
  const bool lines = this->StyleNeedsLines();

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
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);

  in.Targets.Ensure(window, frame.Size[0], frame.Size[1], this->ChooseThicknessFactor(frame), in.Particles.HasColors(),
                    lines);
  frame.Framebuffer = in.Targets.Framebuffer;
  // The opaque scene drawn so far: its depth (occlusion) and, for refraction, its colour.
  in.Targets.CopyOpaqueScene(frame, refraction);
  shared.Composite(frame, in.Targets, refraction);

  // The offscreen passes, over the fluid's rectangle.
  state->PushFramebufferBindings();
  frame.Framebuffer->Bind();
  state->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(frame.RectMin[0], frame.RectMin[1], frame.RectWidth(), frame.RectHeight());
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  if (!in.Splats.Prepare(frame, in.Particles, in.Targets, thickness))
  {
    state->PopFramebufferBindings();
    vtkErrorMacro("The screen-space fluid splat shader did not compile (see the messages above).");
    return;
  }
  in.Splats.Run(frame, in.Particles, in.Targets, thickness);
  this->LastThicknessFactor = in.Splats.LastThicknessFactor();
  if (thickness)
  {
    in.ThicknessBlur.Run(frame, in.Targets, this->MaxFilterRadius);
  }
  int depth = 0; // the target holding the depth the shading reads
  this->LastSmoothingFactor = 1;
  if (smooth)
  {
    parafluid::FluidDepthSmoothingPass::Settings smoothing;
    smoothing.Method = this->SmoothingMethod;
    smoothing.Iterations = this->SmoothingIterations;
    smoothing.FilterSize = this->FilterSize;
    smoothing.MaxFilterRadius = this->MaxFilterRadius;
    smoothing.SpreadTaps = this->SpreadFilterTaps;
    smoothing.DepthRange = this->DepthRange;
    smoothing.CurvatureFlowStep = this->CurvatureFlowStep;
    depth = in.Smoothing.Run(frame, in.Targets, smoothing);
    this->LastSmoothingFactor = in.Smoothing.LastFactor();
  }
  this->RunStylePasses(frame, in.Targets, depth);
  frame.Framebuffer->RemoveColorAttachment(0);
  state->PopFramebufferBindings();

  // Into the view, with depth so the opaque scene occludes and is occluded.
  parafluid::FluidShadePass::Inputs inputs;
  inputs.Depth = depth;
  inputs.Thickness = thickness;
  inputs.OpaqueColor = refraction;
  inputs.ParticleColors = in.Particles.HasColors();
  inputs.Lines = lines;
  parafluid::FluidShadeSettings shading;
  this->FillShading(shading);
  in.Shade.Run(frame, in.Targets, inputs, in.Environment, shading);
  this->DrawOverSurface(frame, in.Targets, depth);
  this->LastPassCount = frame.PassCount;
  // Report, do not hide, a GL error of these passes (release VTK builds check none).
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
  {
    vtkErrorMacro("OpenGL error 0x" << std::hex << error << std::dec << " in the screen-space fluid passes.");
  }
}

//------------------------------------------------------------------------------
// Style hooks: the plain fluid has none.
void vtkPFScreenSpaceFluidMapper::PrepareStyle(vtkPointSet*, vtkUnsignedCharArray*, vtkOpenGLRenderWindow*,
                                               vtkMTimeType)
{
}

void vtkPFScreenSpaceFluidMapper::RunStylePasses(parafluid::FluidFrame&, parafluid::FluidScreenTargets&, int) {}

void vtkPFScreenSpaceFluidMapper::DrawOverSurface(parafluid::FluidFrame&, parafluid::FluidScreenTargets&, int) {}

void vtkPFScreenSpaceFluidMapper::ReleaseStyle(vtkWindow*) {}

void vtkPFScreenSpaceFluidMapper::FillShading(parafluid::FluidShadeSettings& shading) const
{
  shading.DisplayMode = this->DisplayMode;
  shading.SmoothSilhouettes =
    this->SmoothSilhouettes && this->DisplayMode != ParticleDepth && this->SmoothingIterations > 0;
  std::copy(this->FluidColor, this->FluidColor + 3, shading.FluidColor);
  shading.AttenuationDistance = this->AttenuationDistance;
  shading.RefractiveIndex = this->RefractiveIndex;
  shading.RefractionStrength = this->RefractionStrength;
  shading.Shininess = this->Shininess;
  shading.SpecularStrength = this->SpecularStrength;
  shading.Ambient = this->Ambient;
  shading.ColorMix = this->ColorMix;
  // Toon bands and lines belong to the styles; without one they are not drawn.
  shading.ToonBands = 4;
  std::fill(shading.LineColor, shading.LineColor + 3, 0.0);
  shading.DepthContourSpacing = 0.0;
}

double vtkPFScreenSpaceFluidMapper::GetUploadedMaxRadius() const
{
  return this->Internal->Particles.MaxRadius();
}
