#include "vtkPFScreenSpaceFluidMapper.h"
#include "FluidBrushStrokePass.h"

#include "FluidBilateralFS.h"
#include "FluidCurvatureFlowFS.h"
#include "FluidNarrowRangeFS.h"
#include "FluidScreenCommon.h"
#include "FluidShadeFS.h"
#include "FluidSplatFS.h"
#include "FluidSplatVS.h"
#include "FluidGaussianBlurFS.h"
#include "FluidToonDoGFS.h"
#include "FluidToonFlowFS.h"
#include "FluidToonTensorFS.h"
#include "parafluid/npr/BrushStrokes.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPFScreenSpaceFluidMapper);

namespace
{
/// A screen-space pass program built once per context from the shared prelude and its body.
std::unique_ptr<vtkOpenGLQuadHelper> makeQuad(
  vtkOpenGLRenderWindow* window, const char* body, const char* defines = "")
{
  std::string fs = std::string("//VTK::System::Dec\n") + defines + FluidScreenCommon + body;
  return std::unique_ptr<vtkOpenGLQuadHelper>(new vtkOpenGLQuadHelper(window, nullptr, fs.c_str(), ""));
}

vtkSmartPointer<vtkTextureObject> makeTarget(vtkOpenGLRenderWindow* window)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture;
}

/// Row vector times a VTK "key" matrix (stored transposed for OpenGL): the math product M x.
std::array<double, 4> transformPoint(vtkMatrix4x4* transposed, const double x[3])
{
  std::array<double, 4> out{};
  for (int c = 0; c < 4; ++c)
  {
    out[c] = x[0] * transposed->GetElement(0, c) + x[1] * transposed->GetElement(1, c) +
      x[2] * transposed->GetElement(2, c) + transposed->GetElement(3, c);
  }
  return out;
}
}

struct vtkPFScreenSpaceFluidMapper::Internals
{
  vtkOpenGLRenderWindow* Context = nullptr;
  // Particles: xyz + radius (float4) and optional RGBA8 colours, as texture buffers.
  vtkSmartPointer<vtkOpenGLBufferObject> ParticleBuffer, ColorBuffer;
  vtkSmartPointer<vtkTextureObject> ParticleTexture, ColorTexture;
  vtkMTimeType UploadedKey = 0;
  vtkIdType Count = 0;
  double MaxRadius = 0.0;
  bool HasColors = false;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };

  // Screen targets, the size of the viewport.
  vtkSmartPointer<vtkTextureObject> OpaqueDepth, OpaqueColor, SplatDepth, ParticleColors;
  std::array<vtkSmartPointer<vtkTextureObject>, 2> Depth, Thickness;
  // Toon display only: the structure tensor (and its blur), and the line coverage.
  std::array<vtkSmartPointer<vtkTextureObject>, 2> Tensor;
  vtkSmartPointer<vtkTextureObject> Lines;
  int Width = 0, Height = 0;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  // Core profiles draw only with a vertex array bound, even one without attributes.
  GLuint EmptyVAO = 0;
  float MaxPointSize = 0.0f; // the context's largest point sprite, pixels (0: not asked yet)
  int ThicknessFactor = 0;   // full-resolution pixels per thickness pixel, each way
  // Splat programs: depth (0) or thickness (1), + 2 for point sprites; built apart so that no
  // pass carries another's branches and varyings (on llvmpipe the thickness pass's branches cost
  // the depth pass a third of its speed).
  vtkShaderProgram* SplatPrograms[4] = { nullptr, nullptr, nullptr, nullptr };
  std::unique_ptr<vtkOpenGLQuadHelper> NarrowRange, Bilateral, Curvature, Blur, Shade, ShadeCube;
  std::unique_ptr<vtkOpenGLQuadHelper> ToonTensor, ToonDoG, ToonFlow;
  vtkSmartPointer<vtkTexture> Environment;
  // Brush-stroke display only: the strokes, laid out again when the data or settings change.
  parafluid::FluidBrushStrokePass Strokes;
  vtkMTimeType StrokeKey = 0;

  void Release(vtkWindow* window)
  {
    for (vtkTextureObject* t : { this->ParticleTexture.Get(), this->ColorTexture.Get(), this->OpaqueDepth.Get(),
           this->OpaqueColor.Get(), this->SplatDepth.Get(), this->ParticleColors.Get(), this->Depth[0].Get(),
           this->Depth[1].Get(), this->Thickness[0].Get(), this->Thickness[1].Get(), this->Tensor[0].Get(),
           this->Tensor[1].Get(), this->Lines.Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
      }
    }
    this->Strokes.Release(window);
    this->StrokeKey = 0;
    if (this->ParticleBuffer)
    {
      this->ParticleBuffer->ReleaseGraphicsResources();
    }
    if (this->ColorBuffer)
    {
      this->ColorBuffer->ReleaseGraphicsResources();
    }
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(window);
    }
    if (this->EmptyVAO && window)
    {
      static_cast<vtkOpenGLRenderWindow*>(window)->MakeCurrent();
      glDeleteVertexArrays(1, &this->EmptyVAO);
    }
    for (auto* quad : { &this->NarrowRange, &this->Bilateral, &this->Curvature, &this->Blur, &this->Shade,
           &this->ShadeCube, &this->ToonTensor, &this->ToonDoG, &this->ToonFlow })
    {
      if (*quad)
      {
        (*quad)->ReleaseGraphicsResources(window);
        quad->reset();
      }
    }
    if (this->Environment)
    {
      this->Environment->ReleaseGraphicsResources(window);
    }
    this->ParticleBuffer = this->ColorBuffer = nullptr;
    this->ParticleTexture = this->ColorTexture = this->OpaqueDepth = this->OpaqueColor = nullptr;
    this->SplatDepth = this->ParticleColors = nullptr;
    this->Depth = {};
    this->Thickness = {};
    this->Tensor = {};
    this->Lines = nullptr;
    this->Framebuffer = nullptr;
    this->EmptyVAO = 0;
    std::fill(std::begin(this->SplatPrograms), std::end(this->SplatPrograms), nullptr);
    this->UploadedKey = 0;
    this->Width = this->Height = 0;
    this->Context = nullptr;
  }

  /// (Re)creates the screen targets for a viewport of width x height.
  /// `thicknessFactor`: full-resolution pixels per thickness pixel, each way.
  void EnsureTargets(vtkOpenGLRenderWindow* window, int width, int height, int thicknessFactor, bool colors, bool toon)
  {
    if (!this->Framebuffer)
    {
      this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->Framebuffer->SetContext(window);
      glGenVertexArrays(1, &this->EmptyVAO);
    }
    const bool resize = width != this->Width || height != this->Height;
    const bool resizeThickness = resize || thicknessFactor != this->ThicknessFactor;
    auto single = [&](vtkSmartPointer<vtkTextureObject>& t, int w, int h, bool linear, bool changed) {
      if (!t)
      {
        t = makeTarget(window);
        t->SetInternalFormat(GL_R32F);
        t->SetFormat(GL_RED);
        if (linear)
        {
          t->SetMinificationFilter(vtkTextureObject::Linear);
          t->SetMagnificationFilter(vtkTextureObject::Linear);
        }
        t->Allocate2D(w, h, 1, VTK_FLOAT);
      }
      else if (changed)
      {
        t->Resize(w, h);
      }
    };
    single(this->Depth[0], width, height, false, resize);
    single(this->Depth[1], width, height, false, resize);
    const int tw = (width + thicknessFactor - 1) / thicknessFactor, th = (height + thicknessFactor - 1) / thicknessFactor;
    single(this->Thickness[0], tw, th, true, resizeThickness);
    single(this->Thickness[1], tw, th, true, resizeThickness);
    this->ThicknessFactor = thicknessFactor;
    auto depth = [&](vtkSmartPointer<vtkTextureObject>& t) {
      if (!t)
      {
        t = makeTarget(window);
        t->AllocateDepth(width, height, vtkTextureObject::Float32);
      }
      else if (resize)
      {
        t->Resize(width, height);
      }
    };
    depth(this->OpaqueDepth);
    depth(this->SplatDepth);
    auto rgba = [&](vtkSmartPointer<vtkTextureObject>& t) {
      if (!t)
      {
        t = makeTarget(window);
        t->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
      }
      else if (resize)
      {
        t->Resize(width, height);
      }
    };
    rgba(this->OpaqueColor);
    if (colors || this->ParticleColors)
    {
      rgba(this->ParticleColors);
    }
    if (toon || this->Lines)
    {
      for (auto& t : this->Tensor)
      {
        if (!t)
        {
          t = makeTarget(window);
          t->SetInternalFormat(GL_RGBA32F);
          t->SetFormat(GL_RGBA);
          t->Allocate2D(width, height, 4, VTK_FLOAT);
        }
        else if (resize)
        {
          t->Resize(width, height);
        }
      }
      single(this->Lines, width, height, false, resize);
    }
    this->Width = width;
    this->Height = height;
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

void vtkPFScreenSpaceFluidMapper::SetStrokeVelocityArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->StrokeVelocityArray)
  {
    this->StrokeVelocityArray = value;
    this->Modified();
  }
}

void vtkPFScreenSpaceFluidMapper::SetStrokeColorArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->StrokeColorArray)
  {
    this->StrokeColorArray = value;
    this->Modified();
  }
}

void vtkPFScreenSpaceFluidMapper::LayOutStrokes(
  vtkPointSet* input, vtkUnsignedCharArray* colors, vtkOpenGLRenderWindow* window)
{
  Internals& in = *this->Internal;
  // The finite particles, and where each came from.
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* velocities = input->GetPointData()->GetArray(this->StrokeVelocityArray.c_str());
  if (velocities && velocities->GetNumberOfComponents() != 3)
  {
    velocities = nullptr;
  }
  if (!velocities)
  {
    vtkWarningMacro("Brush strokes: no 3-component point array '" << this->StrokeVelocityArray
                                                                  << "'; the water is taken as still (fixed strokes only).");
  }
  vtkDataArray* values = input->GetPointData()->GetArray(this->StrokeColorArray.c_str());
  std::vector<float> xyz, velocity, value;
  std::vector<vtkIdType> source;
  xyz.reserve(static_cast<size_t>(3 * n));
  velocity.reserve(static_cast<size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], v[3] = { 0.0, 0.0, 0.0 };
    input->GetPoint(i, x);
    if (velocities)
    {
      velocities->GetTuple(i, v);
    }
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      xyz.push_back(static_cast<float>(x[k]));
      velocity.push_back(std::isfinite(v[k]) ? static_cast<float>(v[k]) : 0.0f);
    }
    value.push_back(values ? static_cast<float>(values->GetComponent(i, 0)) : 0.0f);
    source.push_back(i);
  }
  parafluid::npr::BrushStrokeParameters parameters;
  // A particle's drawn radius is half a spacing to a spacing: the flow is read over about two to
  // four spacings.
  parameters.flow.kernelRadius = 4.0 * in.MaxRadius;
  parameters.flow.seedStride = this->StrokeSeedStride;
  parameters.flow.pointsPerLine = 12;
  parameters.flow.lineDuration = this->StrokeDuration;
  parameters.flow.maxLines = static_cast<std::size_t>(this->MaxStrokes);
  parameters.strokeLength = this->StrokeLength * in.MaxRadius;
  // Three fixed strokes per stroke length each way: on screen they overlap into a painted cover.
  parameters.fillSpacing = parameters.strokeLength / 3.0;
  parameters.maxStrokes = static_cast<std::size_t>(this->MaxStrokes);
  parafluid::npr::BrushStrokeSet strokes;
  try
  {
    strokes = parafluid::npr::layoutBrushStrokes(xyz.data(), velocity.data(), value.data(), source.size(), parameters);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Brush strokes: " << e.what());
  }
  // Colours: the scalar colouring, else the colour array from dark to light fluid colour.
  const std::size_t count = strokes.strokeCount();
  std::vector<float> rgb(3 * count);
  float low = std::numeric_limits<float>::max(), high = -low;
  for (float v : strokes.value)
  {
    low = std::min(low, v);
    high = std::max(high, v);
  }
  for (std::size_t s = 0; s < count; ++s)
  {
    const vtkIdType particle = source[strokes.seed[s]];
    for (int k = 0; k < 3; ++k)
    {
      if (colors)
      {
        const int nc = colors->GetNumberOfComponents();
        rgb[3 * s + k] = colors->GetValue(nc * particle + (nc >= 3 ? k : 0)) / 255.0f;
      }
      else
      {
        const double t = values && high > low ? (strokes.value[s] - low) / (high - low) : 0.5;
        const double dark = 0.6 * this->FluidColor[k], light = this->FluidColor[k] + 0.6 * (1.0 - this->FluidColor[k]);
        rgb[3 * s + k] = static_cast<float>(dark + t * (light - dark));
      }
    }
  }
  in.Strokes.Upload(window, strokes, rgb);
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
void vtkPFScreenSpaceFluidMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  Internals& in = *this->Internal;
  this->LastPassCount = 0;
  this->LastUsedPointSprites = false;
  this->LastThicknessFactor = 0;
  std::fill(this->LastScreenRect, this->LastScreenRect + 4, 0);
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

  // --- Particles to the GPU when the data, the radius or the colouring changed.
  int cellFlag = 0;
  vtkUnsignedCharArray* colors = this->ScalarVisibility ? this->MapScalars(input, 1.0, cellFlag) : nullptr;
  if (colors && (cellFlag != 0 || colors->GetNumberOfTuples() != input->GetNumberOfPoints()))
  {
    colors = nullptr; // cell colours have no particle to sit on
  }
  vtkMTimeType key = std::max(input->GetMTime(), this->GetMTime());
  if (colors)
  {
    key = std::max(key, colors->GetMTime());
  }
  if (key != in.UploadedKey || (colors != nullptr) != in.HasColors || !in.ParticleTexture)
  {
    const vtkIdType n = input->GetNumberOfPoints();
    vtkDataArray* radii = this->RadiusArray.empty() ? nullptr : input->GetPointData()->GetArray(this->RadiusArray.c_str());
    std::vector<float> packed(static_cast<size_t>(4 * n));
    double maxRadius = 0.0;
    vtkMath::UninitializeBounds(in.Bounds);
    double box[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      input->GetPoint(i, x);
      double r = radii ? radii->GetComponent(i, 0) : this->ParticleRadius;
      const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(r);
      if (!finite || r <= 0.0)
      {
        r = 0.0; // the vertex shader drops it: a NaN particle must not poison the picture
      }
      else
      {
        maxRadius = std::max(maxRadius, r);
        for (int k = 0; k < 3; ++k)
        {
          box[2 * k] = std::min(box[2 * k], x[k]);
          box[2 * k + 1] = std::max(box[2 * k + 1], x[k]);
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        packed[4 * i + k] = finite ? static_cast<float>(x[k]) : 0.0f;
      }
      packed[4 * i + 3] = static_cast<float>(r);
    }
    if (maxRadius > 0.0)
    {
      std::copy(box, box + 6, in.Bounds);
    }
    if (!in.ParticleBuffer)
    {
      in.ParticleBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
      in.ParticleBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
      in.ParticleTexture = makeTarget(window);
    }
    in.ParticleBuffer->Upload(packed, vtkOpenGLBufferObject::TextureBuffer);
    in.ParticleTexture->ReleaseGraphicsResources(window);
    in.ParticleTexture->CreateTextureBuffer(static_cast<unsigned int>(n), 4, VTK_FLOAT, in.ParticleBuffer);
    in.HasColors = colors != nullptr;
    if (colors)
    {
      if (!in.ColorBuffer)
      {
        in.ColorBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
        in.ColorBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
        in.ColorTexture = makeTarget(window);
      }
      // MapScalars gives 4 components for RGBA lookup tables and may give fewer otherwise.
      std::vector<unsigned char> rgba(static_cast<size_t>(4 * n), 255);
      const int nc = colors->GetNumberOfComponents();
      for (vtkIdType i = 0; i < n; ++i)
      {
        const unsigned char* c = colors->GetPointer(nc * i);
        for (int k = 0; k < 3; ++k)
        {
          rgba[4 * i + k] = c[nc >= 3 ? k : 0];
        }
      }
      in.ColorBuffer->Upload(rgba, vtkOpenGLBufferObject::TextureBuffer);
      in.ColorTexture->ReleaseGraphicsResources(window);
      in.ColorTexture->CreateTextureBuffer(static_cast<unsigned int>(n), 4, VTK_UNSIGNED_CHAR, in.ColorBuffer);
    }
    in.Count = n;
    in.MaxRadius = maxRadius;
    in.UploadedKey = key;
  }
  if (in.MaxRadius <= 0.0)
  {
    return; // nothing finite to draw
  }
  this->LastStrokeCount = 0;
  this->LastStrokeSegmentCount = 0;
  if (this->DisplayMode == BrushStrokes)
  {
    if (key != in.StrokeKey)
    {
      this->LayOutStrokes(input, colors, window);
      in.StrokeKey = key;
    }
    this->LastStrokeCount = static_cast<vtkIdType>(in.Strokes.StrokeCount());
    this->LastStrokeSegmentCount = static_cast<vtkIdType>(in.Strokes.SegmentCount());
  }

  // --- Camera: the key matrices are stored transposed, ready for SetUniformMatrix.
  int width = 0, height = 0, originX = 0, originY = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (width <= 0 || height <= 0)
  {
    return;
  }
  auto* camera = static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera());
  vtkMatrix4x4 *wcvc = nullptr, *vcdc = nullptr, *wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  camera->GetKeyMatrices(renderer, wcvc, normals, vcdc, wcdc);
  vtkNew<vtkMatrix4x4> mcvc;
  mcvc->DeepCopy(wcvc);
  if (actor && !actor->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc = nullptr;
    vtkMatrix3x3* actorNormals = nullptr;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, actorNormals);
    vtkMatrix4x4::Multiply4x4(mcwc, wcvc, mcvc);
  }
  const bool parallel = camera->GetParallelProjection() != 0;
  const double nearDistance = camera->GetClippingRange()[0];
  float projection[4];
  projection[0] = static_cast<float>(vcdc->GetElement(0, 0));
  projection[1] = static_cast<float>(vcdc->GetElement(1, 1));
  projection[2] = static_cast<float>(vcdc->GetElement(parallel ? 3 : 2, 0));
  projection[3] = static_cast<float>(vcdc->GetElement(parallel ? 3 : 2, 1));

  // --- Where the fluid is on screen: its bounds (grown by the radius) projected.
  int rect[4] = { 0, 0, width, height };
  double nearest = VTK_DOUBLE_MAX, farthest = 0.0;
  bool pointSprites = false;
  {
    bool behindEye = false;
    double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, hi[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    double slope[2] = { 0.0, 0.0 }; // largest |x| / -z and |y| / -z over the grown bounds
    for (int corner = 0; corner < 8; ++corner)
    {
      const double x[3] = { in.Bounds[(corner & 1) ? 1 : 0] + ((corner & 1) ? in.MaxRadius : -in.MaxRadius),
        in.Bounds[(corner & 2) ? 3 : 2] + ((corner & 2) ? in.MaxRadius : -in.MaxRadius),
        in.Bounds[(corner & 4) ? 5 : 4] + ((corner & 4) ? in.MaxRadius : -in.MaxRadius) };
      const auto eye = transformPoint(mcvc, x);
      const double distance = -eye[2];
      nearest = std::min(nearest, distance);
      farthest = std::max(farthest, distance);
      if (!parallel && distance <= nearDistance)
      {
        behindEye = true;
        continue;
      }
      for (int k = 0; k < 2; ++k)
      {
        slope[k] = distance > 0.0 ? std::max(slope[k], std::abs(eye[k]) / distance) : VTK_DOUBLE_MAX;
      }
      double e[3] = { eye[0], eye[1], eye[2] };
      const auto clip = transformPoint(vcdc, e);
      for (int k = 0; k < 2; ++k)
      {
        const double ndc = clip[k] / clip[3];
        lo[k] = std::min(lo[k], ndc);
        hi[k] = std::max(hi[k], ndc);
      }
    }
    if (farthest <= nearDistance && !parallel)
    {
      return; // all behind the camera
    }
    if (!behindEye)
    {
      const int margin = this->MaxFilterRadius + 2;
      const int size[2] = { width, height };
      for (int k = 0; k < 2; ++k)
      {
        const double a = (0.5 * lo[k] + 0.5) * size[k] - margin;
        const double b = (0.5 * hi[k] + 0.5) * size[k] + margin;
        rect[k] = static_cast<int>(std::floor(std::max(0.0, std::min(a, double(size[k])))));
        rect[k + 2] = static_cast<int>(std::ceil(std::max(0.0, std::min(b, double(size[k])))));
      }
    }
    if (rect[2] <= rect[0] || rect[3] <= rect[1])
    {
      return; // off screen
    }
    // One point per particle instead of a six-vertex quad, when that is safe: every sphere's
    // centre projects inside the viewport (the grown bounds do; a point whose centre is clipped
    // is dropped whole) and no sphere's box exceeds the largest point size. The bound on the box
    // is the vertex shader's tangent-plane extent at the nearest depth and the widest angle.
    if (in.MaxPointSize <= 0.0f)
    {
      GLfloat range[2] = { 0.0f, 0.0f };
      glGetFloatv(GL_POINT_SIZE_RANGE, range);
      in.MaxPointSize = std::max(1.0f, range[1]);
    }
    const bool allOnScreen = !behindEye && lo[0] >= -1.0 && hi[0] <= 1.0 && lo[1] >= -1.0 && hi[1] <= 1.0;
    if (allOnScreen)
    {
      const double r = in.MaxRadius;
      const double d = nearest + r; // the nearest a centre can be
      const int size[2] = { width, height };
      double largest = 0.0;
      for (int k = 0; k < 2; ++k)
      {
        const double p = vcdc->GetElement(k, k);
        const double ndcWidth = parallel ? 2.0 * r * p
                                         : p * 2.0 * r * d * std::sqrt(1.0 + slope[k] * slope[k]) / (d * d - r * r);
        largest = std::max(largest, 0.5 * ndcWidth * size[k]);
      }
      pointSprites = (parallel || nearest > 0.0) && largest + 3.0 <= in.MaxPointSize;
    }
  }
  this->LastUsedPointSprites = pointSprites;
  std::copy(rect, rect + 4, this->LastScreenRect);
  const int rectMin[2] = { rect[0], rect[1] };
  const int rectMax[2] = { rect[2], rect[3] };
  const int rectSize[2] = { rect[2] - rect[0], rect[3] - rect[1] };

  const int mode = this->DisplayMode;
  const bool needThickness = mode == TransparentFluid || mode == Thickness;
  const bool needOpaqueColor = mode == TransparentFluid;
  const bool smooth = mode != ParticleDepth && this->SmoothingIterations > 0;

  vtkOpenGLState* state = window->GetState();
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

  // Thickness is blurred anyway, so it is splatted at reduced resolution: half, or a quarter when
  // particles are small on screen (radius under 8 pixels at the fluid's middle depth), where
  // the fill of a million overlapping splats would dominate the frame. Particles under 1.5
  // thickness pixels deposit their volume on the 4 nearest pixels instead of sampling their chord
  // (FluidSplatVS.glsl), so the thickness stays the fluid's volume per unit area at any size.
  int thicknessFactor = 2;
  {
    const double middle = parallel ? 1.0 : std::max(0.5 * (nearest + farthest), 1e-12);
    const double radiusPixels = in.MaxRadius * vcdc->GetElement(1, 1) * 0.5 * height / middle;
    thicknessFactor = radiusPixels < 8.0 ? 4 : 2;
  }
  in.EnsureTargets(window, width, height, thicknessFactor, in.HasColors, this->DisplayMode == Toon);

  // --- The opaque scene drawn so far: its depth (occlusion) and, for refraction, its colour.
  // Read from the framebuffer being drawn (the read binding may point elsewhere, e.g. at
  // ParaView's display buffer).
  GLint drawFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
  // (vtkTextureObject::CopyFromFrameBuffer re-creates the texture at the copied size; the
  // targets must keep the viewport's size, so copy into the rectangle ourselves.)
  auto copyRect = [&](vtkTextureObject* target) {
    target->Bind();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, rect[0], rect[1], originX + rect[0], originY + rect[1], rectSize[0], rectSize[1]);
    target->Deactivate();
  };
  copyRect(in.OpaqueDepth);
  if (needOpaqueColor)
  {
    copyRect(in.OpaqueColor);
  }
  state->PopReadFramebufferBinding();

  state->PushFramebufferBindings();
  vtkOpenGLFramebufferObject* fbo = in.Framebuffer;
  fbo->Bind();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(rect[0], rect[1], rectSize[0], rectSize[1]);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);

  // --- Pass 1 (and 3): sphere splats.
  const float fullSize[2] = { static_cast<float>(width), static_cast<float>(height) };
  auto splatProgram = [&](int which) -> vtkShaderProgram* {
    vtkShaderProgram*& program = in.SplatPrograms[which + (pointSprites ? 2 : 0)];
    if (!program)
    {
      std::string vs = FluidSplatVS, fs = FluidSplatFS;
      std::string defines = "//VTK::System::Dec\n";
      defines += which == 1 ? "#define THICKNESS_PASS\n" : "";
      defines += pointSprites ? "#define POINT_SPRITES\n" : "";
      vtkShaderProgram::Substitute(vs, "//VTK::System::Dec\n", defines);
      vtkShaderProgram::Substitute(fs, "//VTK::System::Dec\n", defines);
      program = window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(program);
    }
    if (!program)
    {
      return nullptr;
    }
    program->SetUniformi("particles", in.ParticleTexture->GetTextureUnit());
    program->SetUniformi("hasColors", in.HasColors ? 1 : 0);
    // Unused without colours, but a sampler left on unit 0 could alias a different sampler type.
    program->SetUniformi(
      "particleColors", (in.HasColors ? in.ColorTexture : in.ParticleTexture)->GetTextureUnit());
    program->SetUniformi("opaqueDepth", in.OpaqueDepth->GetTextureUnit());
    program->SetUniformi("useOpaqueDepth", 1);
    program->SetUniformf("opaqueDepthScale", 1.0f);
    program->SetUniformMatrix("MCVCMatrix", mcvc);
    program->SetUniformMatrix("VCDCMatrix", vcdc);
    program->SetUniformi("parallelProjection", parallel ? 1 : 0);
    program->SetUniformf("nearDistance", static_cast<float>(nearDistance));
    program->SetUniform4f("projection", projection);
    program->SetUniform2f("targetSize", fullSize);
    return program;
  };
  in.ParticleTexture->Activate();
  if (in.HasColors)
  {
    in.ColorTexture->Activate();
  }
  in.OpaqueDepth->Activate();
  auto releaseSplatTextures = [&]() {
    in.ParticleTexture->Deactivate();
    if (in.HasColors)
    {
      in.ColorTexture->Deactivate();
    }
    in.OpaqueDepth->Deactivate();
  };
  // (The thickness program is built first so that a failure stops before any drawing, and the
  // depth program is the one bound for the first pass.)
  if ((needThickness && !splatProgram(1)) || !splatProgram(0))
  {
    releaseSplatTextures();
    state->PopFramebufferBindings();
    vtkErrorMacro("The screen-space fluid splat shader did not compile (see the messages above).");
    return;
  }
  glBindVertexArray(in.EmptyVAO);
  const GLboolean programPointSize = glIsEnabled(GL_PROGRAM_POINT_SIZE);
  if (pointSprites)
  {
    glEnable(GL_PROGRAM_POINT_SIZE);
  }
  auto drawSplats = [&]() {
    if (pointSprites)
    {
      glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(in.Count));
    }
    else
    {
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * in.Count));
    }
  };

  fbo->AddColorAttachment(0, in.Depth[0]);
  if (in.HasColors)
  {
    fbo->AddColorAttachment(1, in.ParticleColors);
  }
  fbo->AddDepthAttachment(in.SplatDepth);
  fbo->ActivateDrawBuffers(in.HasColors ? 2 : 1);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDisable(GL_BLEND);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  drawSplats();
  ++this->LastPassCount;
  if (in.HasColors)
  {
    fbo->RemoveColorAttachment(1);
  }
  fbo->RemoveDepthAttachment();
  fbo->ActivateDrawBuffers(1);

  const int f = thicknessFactor;
  const int thicknessSize[2] = { (width + f - 1) / f, (height + f - 1) / f };
  const int thicknessMin[2] = { rect[0] / f, rect[1] / f };
  const int thicknessMax[2] = { (rect[2] + f - 1) / f, (rect[3] + f - 1) / f };
  const float thicknessPixels[2] = { static_cast<float>(thicknessSize[0]), static_cast<float>(thicknessSize[1]) };
  if (needThickness)
  {
    vtkShaderProgram* thicknessProgram = splatProgram(1);
    fbo->AddColorAttachment(0, in.Thickness[0]);
    state->vtkglViewport(0, 0, thicknessSize[0], thicknessSize[1]);
    state->vtkglScissor(thicknessMin[0], thicknessMin[1], thicknessMax[0] - thicknessMin[0], thicknessMax[1] - thicknessMin[1]);
    thicknessProgram->SetUniformf("opaqueDepthScale", static_cast<float>(f));
    this->LastThicknessFactor = f;
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    thicknessProgram->SetUniform2f("targetSize", thicknessPixels);
    drawSplats();
    state->vtkglDisable(GL_BLEND);
    ++this->LastPassCount;
  }
  glBindVertexArray(0);
  if (!programPointSize)
  {
    glDisable(GL_PROGRAM_POINT_SIZE);
  }
  releaseSplatTextures();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);

  auto commonUniforms = [&](vtkShaderProgram* program) {
    const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };
    program->SetUniform2i("rectMin", rectMin);
    program->SetUniform2i("rectMax", rectMax);
    program->SetUniform2f("viewportSize", viewport);
    program->SetUniformi("parallelProjection", parallel ? 1 : 0);
    program->SetUniform4f("projection", projection);
  };
  // One full-screen pass (clipped to the fluid's rectangle) from `source` into `target`.
  auto filterPass = [&](vtkOpenGLQuadHelper* quad, vtkTextureObject* source, vtkTextureObject* target,
                      const char* sourceName) {
    fbo->AddColorAttachment(0, target);
    source->Activate();
    quad->Program->SetUniformi(sourceName, source->GetTextureUnit());
    quad->Render();
    source->Deactivate();
    ++this->LastPassCount;
  };

  // --- Pass 3b: blur the thickness (separable Gaussian).
  if (needThickness)
  {
    if (!in.Blur)
    {
      in.Blur = makeQuad(window, FluidGaussianBlurFS);
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(in.Blur->Program);
    }
    vtkShaderProgram* program = in.Blur->Program;
    program->SetUniform2i("rectMin", thicknessMin);
    program->SetUniform2i("rectMax", thicknessMax);
    program->SetUniform2f("viewportSize", thicknessPixels);
    program->SetUniformi("radius", std::max(1, (this->MaxFilterRadius + f) / (2 * f)));
    const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
    program->SetUniform2i("stepDir", dx);
    filterPass(in.Blur.get(), in.Thickness[0], in.Thickness[1], "sourceTex");
    program->SetUniform2i("stepDir", dy);
    filterPass(in.Blur.get(), in.Thickness[1], in.Thickness[0], "sourceTex");
    state->vtkglViewport(0, 0, width, height);
    state->vtkglScissor(rect[0], rect[1], rectSize[0], rectSize[1]);
  }

  // --- Pass 2: smooth the depth.
  int current = 0;
  if (smooth)
  {
    std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->SmoothingMethod == NarrowRange
      ? in.NarrowRange
      : (this->SmoothingMethod == Bilateral ? in.Bilateral : in.Curvature);
    if (!quad)
    {
      quad = makeQuad(window,
        this->SmoothingMethod == NarrowRange ? FluidNarrowRangeFS
                                             : (this->SmoothingMethod == Bilateral ? FluidBilateralFS : FluidCurvatureFlowFS));
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(quad->Program);
    }
    vtkShaderProgram* program = quad->Program;
    commonUniforms(program);
    // The filters work in the radius of the particles on screen: the largest one is the safe
    // choice for the band of depths that count as one surface.
    program->SetUniformf("particleRadius", static_cast<float>(in.MaxRadius));
    program->SetUniformf("rangeFactor", static_cast<float>(this->DepthRange));
    if (this->SmoothingMethod == CurvatureFlow)
    {
      program->SetUniformf("stepFactor", static_cast<float>(this->CurvatureFlowStep));
      for (int i = 0; i < this->SmoothingIterations; ++i)
      {
        filterPass(quad.get(), in.Depth[current], in.Depth[1 - current], "depthTex");
        current = 1 - current;
      }
    }
    else
    {
      program->SetUniformf("filterSize", static_cast<float>(this->FilterSize));
      program->SetUniformi("maxRadius", this->MaxFilterRadius);
      const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
      for (int i = 0; i < this->SmoothingIterations; ++i)
      {
        program->SetUniform2i("stepDir", dx);
        filterPass(quad.get(), in.Depth[0], in.Depth[1], "depthTex");
        program->SetUniform2i("stepDir", dy);
        filterPass(quad.get(), in.Depth[1], in.Depth[0], "depthTex");
      }
    }
  }
  // --- Toon lines: structure tensor of the depth, blurred; difference of Gaussians across the
  // edges; averaged along them (flow-guided DoG) into a line coverage.
  const bool toon = mode == Toon;
  if (toon)
  {
    auto ready = [&](std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* source) {
      if (!quad)
      {
        quad = makeQuad(window, source);
      }
      else
      {
        window->GetShaderCache()->ReadyShaderProgram(quad->Program);
      }
      commonUniforms(quad->Program);
      return quad->Program;
    };
    // The line image: depth in units of DepthRange particle radii; the background three units
    // behind the farthest fluid, so a silhouette is always a strong edge, stronger than any
    // depth step inside the fluid that still counts as one surface.
    const float lineScale = static_cast<float>(1.0 / (in.MaxRadius * this->DepthRange));
    const float background = static_cast<float>(farthest) * lineScale + 3.0f;
    vtkShaderProgram* program = ready(in.ToonTensor, FluidToonTensorFS);
    program->SetUniformf("lineDepthScale", lineScale);
    program->SetUniformf("backgroundValue", background);
    filterPass(in.ToonTensor.get(), in.Depth[current], in.Tensor[0], "depthTex");

    program = ready(in.Blur, FluidGaussianBlurFS);
    const float full[2] = { static_cast<float>(width), static_cast<float>(height) };
    program->SetUniform2f("viewportSize", full);
    program->SetUniformi("radius", 4);
    const int dx[2] = { 1, 0 }, dy[2] = { 0, 1 };
    program->SetUniform2i("stepDir", dx);
    filterPass(in.Blur.get(), in.Tensor[0], in.Tensor[1], "sourceTex");
    program->SetUniform2i("stepDir", dy);
    filterPass(in.Blur.get(), in.Tensor[1], in.Tensor[0], "sourceTex");

    // The DoG goes into the free depth target.
    vtkTextureObject* dog = in.Depth[1 - current];
    program = ready(in.ToonDoG, FluidToonDoGFS);
    program->SetUniformf("lineDepthScale", lineScale);
    program->SetUniformf("backgroundValue", background);
    program->SetUniformf("sigma", static_cast<float>(std::max(0.5, this->LineWidth)));
    in.Tensor[0]->Activate();
    program->SetUniformi("tensorTex", in.Tensor[0]->GetTextureUnit());
    filterPass(in.ToonDoG.get(), in.Depth[current], dog, "depthTex");

    program = ready(in.ToonFlow, FluidToonFlowFS);
    program->SetUniformi("tensorTex", in.Tensor[0]->GetTextureUnit());
    program->SetUniformf("flowSigma", 3.0f);
    program->SetUniformf("threshold", static_cast<float>(this->LineThreshold));
    filterPass(in.ToonFlow.get(), dog, in.Lines, "dogTex");
    in.Tensor[0]->Deactivate();
  }
  fbo->RemoveColorAttachment(0);
  state->PopFramebufferBindings();

  // --- Pass 4: shade into the view, with depth so the opaque scene occludes and is occluded.
  state->vtkglViewport(originX, originY, width, height);
  state->vtkglScissor(originX + rect[0], originY + rect[1], rectSize[0], rectSize[1]);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  // Environment: our cube map, else the renderer's, else the background colours.
  vtkTexture* environment = in.Environment;
  float eyeToCube[9];
  if (!environment && renderer->GetEnvironmentTexture() && renderer->GetEnvironmentTexture()->GetCubeMap())
  {
    environment = renderer->GetEnvironmentTexture();
  }
  if (environment && !environment->GetCubeMap())
  {
    environment = nullptr;
  }
  std::unique_ptr<vtkOpenGLQuadHelper>& shadeQuad = environment ? in.ShadeCube : in.Shade;
  if (!shadeQuad)
  {
    shadeQuad = makeQuad(window, FluidShadeFS, environment ? "#define FLUID_CUBEMAP\n" : "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(shadeQuad->Program);
  }
  vtkShaderProgram* shade = shadeQuad->Program;
  commonUniforms(shade);
  shade->SetUniformMatrix("VCDCMatrix", vcdc);
  shade->SetUniformi("displayMode", mode);
  shade->SetUniformi("toonBands", this->ToonBands);
  shade->SetUniform3f("lineColor", this->LineColor);
  shade->SetUniformf("contourSpacing", static_cast<float>(this->DepthContourSpacing * in.MaxRadius));
  shade->SetUniform3f("fluidColor", this->FluidColor);
  shade->SetUniformf("attenuationDistance", static_cast<float>(this->AttenuationDistance));
  shade->SetUniformf("refractiveIndex", static_cast<float>(this->RefractiveIndex));
  shade->SetUniformf("refractionStrength", static_cast<float>(this->RefractionStrength));
  shade->SetUniformf("shininess", static_cast<float>(this->Shininess));
  shade->SetUniformf("specularStrength", static_cast<float>(this->SpecularStrength));
  shade->SetUniformf("ambient", static_cast<float>(this->Ambient));
  shade->SetUniformf("colorMix", static_cast<float>(this->ColorMix));
  const float depthRange[2] = { static_cast<float>(std::max(nearest, nearDistance)), static_cast<float>(farthest) };
  shade->SetUniform2f("depthRange", depthRange);

  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  // Lights: directions in eye space (the view matrix's rotation), colour x intensity.
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

    // Eye direction -> world (the inverse rotation is the transpose), then world -> cube frame.
    double cubeAxes[3][3] = { { 1, 0, 0 }, { 0, 0, 1 }, { 0, -1, 0 } }; // ParaFluid's: image +Y = world +Z
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
    in.Depth[current]->Activate();
    shade->SetUniformi("depthTex", in.Depth[current]->GetTextureUnit());
    if (needThickness)
    {
      in.Thickness[0]->Activate();
      shade->SetUniformi("thicknessTex", in.Thickness[0]->GetTextureUnit());
      const float toThickness[2] = { 1.0f / (f * thicknessSize[0]), 1.0f / (f * thicknessSize[1]) };
      shade->SetUniform2f("thicknessScale", toThickness);
    }
    if (needOpaqueColor)
    {
      in.OpaqueColor->Activate();
      shade->SetUniformi("opaqueColor", in.OpaqueColor->GetTextureUnit());
    }
    shade->SetUniformi("hasParticleColors", in.HasColors ? 1 : 0);
    if (in.HasColors)
    {
      in.ParticleColors->Activate();
      shade->SetUniformi("particleColorTex", in.ParticleColors->GetTextureUnit());
    }
    if (toon)
    {
      in.Lines->Activate();
      shade->SetUniformi("linesTex", in.Lines->GetTextureUnit());
    }
    shadeQuad->Render();
    ++this->LastPassCount;
    if (toon)
    {
      in.Lines->Deactivate();
    }
    in.Depth[current]->Deactivate();
    if (needThickness)
    {
      in.Thickness[0]->Deactivate();
    }
    if (needOpaqueColor)
    {
      in.OpaqueColor->Deactivate();
    }
    if (in.HasColors)
    {
      in.ParticleColors->Deactivate();
    }
    if (environment)
    {
      environment->PostRender(renderer);
    }
  }
  // --- Pass 5 (brush-stroke display): the strokes over the shaded fluid, on its visible surface.
  if (mode == BrushStrokes && in.Strokes.SegmentCount() > 0)
  {
    parafluid::FluidBrushStrokePass::View strokeView{ mcvc, vcdc, { width, height }, { originX, originY },
      { rectMin[0], rectMin[1] }, { rectMax[0], rectMax[1] }, parallel,
      { projection[0], projection[1], projection[2], projection[3] } };
    state->vtkglDepthMask(GL_FALSE); // the surface's depth is already written
    // A stroke more than 3 particle radii behind the surface runs through hidden water.
    if (!in.Strokes.Draw(window, strokeView, in.Depth[current], in.EmptyVAO, this->StrokeWidth, 3.0 * in.MaxRadius))
    {
      vtkErrorMacro("The brush-stroke shader did not compile (see the messages above).");
    }
    state->vtkglDepthMask(GL_TRUE);
    ++this->LastPassCount;
  }
  // Report, do not hide, a GL error of these passes (release VTK builds check none).
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
  {
    vtkErrorMacro("OpenGL error 0x" << std::hex << error << std::dec << " in the screen-space fluid passes.");
  }
}
