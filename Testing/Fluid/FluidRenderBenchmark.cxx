// Screen-space fluid: depth accuracy against an analytic sphere and frame time, ours beside VTK's
// vtkOpenGLFluidMapper and vtkPointGaussianMapper spheres (the floor), in one run and one window.
//
//   ParaFluidFluidRenderBenchmark [--width W --height H --csv file --big N
//                                  --only accuracy|speed|big|npr]             (benchmark)
//   ParaFluidFluidRenderBenchmark --check                                     (the ctest)
//
// Needs an X display (run under scripts/with-xvfb.sh). Our depth comes from the window's depth
// buffer, which our mapper writes; vtkOpenGLFluidMapper's from its own eye-z target.
#include "FluidScenes.h"
#include "parafluid/surface/ParticleSurface.h"
#include "vtkPFBrushStrokeFluidMapper.h"
#include "vtkPFRayMarchedFluidMapper.h"
#include "vtkPFScreenSpaceFluidActor.h"
#include "vtkPFScreenSpaceFluidMapper.h"
#include "vtkPFToonFluidMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFluidMapper.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
struct DepthError
{
  double rms = 0.0, mean = 0.0; // in particle radii
  double spread = 0.0;          // rms about the mean: the surface's roughness
  double coverage = 0.0;        // share of the measured sphere pixels that have fluid
};

/// The scene: camera on +z looking at the origin, vertical view angle 30 degrees, fixed clipping.
struct Window
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  int width, height;
  double distance = 4.0, nearPlane = 1.0, farPlane = 10.0;

  Window(int w, int h)
    : width(w)
    , height(h)
  {
    window->SetSize(w, h);
    window->SetMultiSamples(0);
    window->OffScreenRenderingOn();
    window->AddRenderer(renderer);
    renderer->SetBackground(0.3, 0.3, 0.35);
    this->ResetCamera();
  }
  void ResetCamera()
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, distance);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    camera->SetClippingRange(nearPlane, farPlane);
  }
  void Render()
  {
    renderer->GetActiveCamera()->SetClippingRange(nearPlane, farPlane);
    renderer->ResetCameraClippingRange(); // keep ours: the next line restores it
    renderer->GetActiveCamera()->SetClippingRange(nearPlane, farPlane);
    window->Render();
    window->WaitForCompletion();
  }

  /// Depth error of what was drawn against a sphere of radius R at the origin, over the pixels
  /// whose sphere normal is within 60 degrees of the view ray (away from the silhouette, where
  /// depth is steep and any filter's error is dominated by the edge).
  DepthError MeasureSphere(double R, double particleRadius)
  {
    std::vector<float> z(static_cast<size_t>(width) * height);
    window->GetZbufferData(0, 0, width - 1, height - 1, z.data());
    // Window depth -> eye distance (perspective); 0 where nothing was drawn.
    for (float& w : z)
    {
      const double ndc = 2.0 * w - 1.0;
      w = w >= 1.0f
            ? 0.0f
            : static_cast<float>(2.0 * nearPlane * farPlane / ((farPlane + nearPlane) - ndc * (farPlane - nearPlane)));
    }
    return this->MeasureSphere(z, R, particleRadius);
  }

  /// As above, from eye distances per pixel (row by row from the bottom; 0: no surface).
  DepthError MeasureSphere(const std::vector<float>& distances, double R, double particleRadius)
  {
    const double t = std::tan(vtkMath::RadiansFromDegrees(15.0));
    const double aspect = static_cast<double>(width) / height;
    double sum = 0.0, sum2 = 0.0;
    long used = 0, seen = 0;
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        // Ray from the eye (origin of eye space) through the pixel centre; sphere at (0, 0, -D).
        double d[3] = { ((i + 0.5) / width * 2.0 - 1.0) * t * aspect, ((j + 0.5) / height * 2.0 - 1.0) * t, -1.0 };
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + 1.0);
        for (double& c : d)
        {
          c /= len;
        }
        const double b = -d[2] * distance; // dot(d, centre)
        const double disc = b * b - (distance * distance - R * R);
        if (disc <= 0.0)
        {
          continue;
        }
        const double hit = b - std::sqrt(disc);
        const double p[3] = { hit * d[0], hit * d[1], hit * d[2] + distance };
        const double cosine = -(p[0] * d[0] + p[1] * d[1] + p[2] * d[2]) / R;
        if (cosine < 0.5)
        {
          continue;
        }
        ++seen;
        const double eyeZ = distances[static_cast<size_t>(j) * width + i];
        if (!(eyeZ > 0.0))
        {
          continue;
        }
        const double error = (eyeZ - (-hit * d[2])) / particleRadius;
        sum += error;
        sum2 += error * error;
        ++used;
      }
    }
    DepthError e;
    if (used > 0)
    {
      e.mean = sum / used;
      e.rms = std::sqrt(sum2 / used);
      e.spread = std::sqrt(std::max(0.0, e.rms * e.rms - e.mean * e.mean));
    }
    e.coverage = seen > 0 ? static_cast<double>(used) / seen : 0.0;
    return e;
  }

  /// Mean seconds per frame over `frames` frames after one warm-up frame (uploads, shaders).
  double FrameTime(int frames)
  {
    this->Render();
    const auto start = std::chrono::steady_clock::now();
    for (int f = 0; f < frames; ++f)
    {
      renderer->GetActiveCamera()->Azimuth(0.2);
      this->Render();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    this->ResetCamera();
    return seconds / frames;
  }
};

/// vtkOpenGLFluidMapper as shipped in VTK 9.2 (ParaView 5.11) never attaches the depth texture of
/// its eye-z framebuffer: it adds the attachment before the framebuffer object exists, which VTK's
/// framebuffer class records but does not attach, and nothing attaches it later. Without a depth
/// test its depth splats keep the last particle drawn, not the nearest (on the ball: the front
/// surface in one quadrant, particles deep inside elsewhere). `Repaired` adds the attachment again
/// once the framebuffer exists, so the comparison is with the peer working as designed; its
/// accuracy is read from its own smoothed eye-z target, as its framebuffer depth is not the surface.
class PeekFluidMapper : public vtkOpenGLFluidMapper
{
public:
  static PeekFluidMapper* New();
  vtkTypeMacro(PeekFluidMapper, vtkOpenGLFluidMapper);
  bool Repaired = true;

  void Render(vtkRenderer* renderer, vtkVolume* volume) override
  {
    if (this->Repaired && this->FBFluidEyeZ)
    {
      this->FBFluidEyeZ->AddDepthAttachment(this->TexBuffer[FluidZ]);
    }
    this->Superclass::Render(renderer, volume);
  }

  /// Eye distance of the smoothed surface per pixel (0 where there is no fluid).
  std::vector<float> SurfaceDistances(double farPlane)
  {
    vtkTextureObject* target = this->TexBuffer[FluidEyeZ];
    const size_t n = static_cast<size_t>(target->GetWidth()) * target->GetHeight();
    std::vector<float> out(n, 0.0f);
    vtkPixelBufferObject* pbo = target->Download();
    if (const float* z = static_cast<const float*>(pbo->MapPackedBuffer()))
    {
      for (size_t k = 0; k < n; ++k)
      {
        out[k] = -z[k] < farPlane ? -z[k] : 0.0f; // cleared past the far plane where empty
      }
      pbo->UnmapPackedBuffer();
    }
    pbo->Delete();
    return out;
  }
};
vtkStandardNewMacro(PeekFluidMapper);

/// The mapper of a display mode: toon and brush strokes are styles with mappers of their own
/// (Representations/NPR) built on the screen-space fluid's passes.
vtkSmartPointer<vtkPFScreenSpaceFluidMapper> fluidMapper(int mode)
{
  if (mode == vtkPFScreenSpaceFluidMapper::Toon)
  {
    return vtkSmartPointer<vtkPFToonFluidMapper>::New();
  }
  if (mode == vtkPFScreenSpaceFluidMapper::BrushStrokes)
  {
    return vtkSmartPointer<vtkPFBrushStrokeFluidMapper>::New();
  }
  auto mapper = vtkSmartPointer<vtkPFScreenSpaceFluidMapper>::New();
  mapper->SetDisplayMode(mode);
  return mapper;
}

vtkSmartPointer<vtkProp> ours(vtkPolyData* data, double radius, int method, int iterations, int mode)
{
  vtkSmartPointer<vtkPFScreenSpaceFluidMapper> mapper = fluidMapper(mode);
  mapper->SetInputDataObject(data);
  mapper->SetParticleRadius(radius);
  mapper->SetSmoothingMethod(method);
  mapper->SetSmoothingIterations(iterations);
  auto actor = vtkSmartPointer<vtkPFScreenSpaceFluidActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkProp> vtkFluid(vtkPolyData* data, double radius, int iterations, bool transparent)
{
  vtkNew<PeekFluidMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetParticleRadius(static_cast<float>(radius));
  mapper->SetSurfaceFilterIterations(static_cast<uint32_t>(iterations));
  mapper->SetSurfaceFilterMethod(vtkOpenGLFluidMapper::NarrowRange);
  mapper->SetDisplayMode(transparent ? vtkOpenGLFluidMapper::TransparentFluidVolume
                                     : (iterations > 0 ? vtkOpenGLFluidMapper::FilteredOpaqueSurface
                                                       : vtkOpenGLFluidMapper::UnfilteredOpaqueSurface));
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  return volume;
}

vtkSmartPointer<vtkProp> gaussianSpheres(vtkPolyData* data, double radius)
{
  vtkNew<vtkPointGaussianMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetScaleFactor(radius);
  mapper->EmissiveOff();
  // The sphere look of ParaView's Point Gaussian "Sphere" preset, in our own words.
  mapper->SetSplatShaderCode("//VTK::Color::Impl\n"
                             "float r2 = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
                             "if (r2 > 1.0) { discard; }\n"
                             "diffuseColor *= 1.0 - r2;\n");
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// How the ray march skips empty space: none (brute force), the occupancy grid only, or with the
/// start/stop splats, one pair for all particles or splash and bulk apart (the default).
enum class Skip
{
  None,
  Occupancy,
  SplatsMerged,
  Splats
};

/// The Ray-Marched Fluid mapper on `data` (spacing d, kernel radius in d, rays per pixel each way).
vtkSmartPointer<vtkProp> rayMarched(vtkPolyData* data, double spacing, int mode, double kernel, double scale,
                                    Skip skip = Skip::Splats)
{
  auto mapper = vtkSmartPointer<vtkPFRayMarchedFluidMapper>::New();
  mapper->SetInputDataObject(data);
  mapper->SetParticleSpacing(spacing);
  mapper->SetKernelRadius(kernel);
  mapper->SetDisplayMode(mode);
  mapper->SetResolutionScale(scale);
  mapper->SetEmptySpaceSkipping(skip != Skip::None);
  mapper->SetStartStopSplats(skip == Skip::SplatsMerged || skip == Skip::Splats);
  mapper->SetSeparateSplash(skip == Skip::Splats);
  auto actor = vtkSmartPointer<vtkPFScreenSpaceFluidActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// Particle Surface's mesh of `data` (marching cubes, cell 0.5 d, 10 Taubin pairs: the filter's
/// defaults but the kernel), drawn by the ordinary polygon mapper; `seconds`: the extraction time.
vtkSmartPointer<vtkProp> meshSurface(vtkPolyData* data, double spacing, double kernel, double& seconds)
{
  const vtkIdType n = data->GetNumberOfPoints();
  std::vector<float> xyz(static_cast<size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      xyz[3 * i + k] = static_cast<float>(x[k]);
    }
  }
  parafluid::surface::ParticleSurfaceParameters parameters;
  parameters.particleSpacing = spacing;
  parameters.kernelRadius = kernel;
  parameters.smoothingIterations = 10;
  parafluid::surface::ParticleSurface extractor;
  const auto start = std::chrono::steady_clock::now();
  const parafluid::surface::SurfaceMesh mesh = extractor.extract(xyz.data(), static_cast<size_t>(n), parameters);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertexCount()));
  std::copy(mesh.points.begin(), mesh.points.end(), static_cast<float*>(points->GetVoidPointer(0)));
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertexCount()));
  std::copy(mesh.normals.begin(), mesh.normals.end(), normals->GetPointer(0));
  vtkNew<vtkCellArray> triangles;
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
  {
    const vtkIdType ids[3] = { mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2] };
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  surface->GetPointData()->SetNormals(normals);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.1, 0.45, 0.75);
  return actor;
}

/// Mean samples of the field per pixel over the window, from the Steps display mode (red counts
/// one level per sample; pixels no ray sampled show the background, counted as 0).
double meanSamples(Window& w)
{
  w.renderer->SetBackground(0.0, 0.0, 0.0);
  w.Render();
  vtkNew<vtkUnsignedCharArray> rgb;
  w.window->GetPixelData(0, 0, w.width - 1, w.height - 1, 0, rgb, 0);
  double sum = 0.0;
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    sum += rgb->GetComponent(i, 0);
  }
  w.renderer->SetBackground(0.3, 0.3, 0.35);
  return sum / (w.width * w.height);
}

void show(Window& w, vtkProp* prop)
{
  w.renderer->RemoveAllViewProps();
  w.renderer->AddViewProp(prop);
}

int failures = 0;
void expect(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  failures += ok ? 0 : 1;
}

vtkPFScreenSpaceFluidMapper* lastMapper(Window& w)
{
  auto* actor = vtkActor::SafeDownCast(w.renderer->GetViewProps()->GetLastProp());
  return actor ? vtkPFScreenSpaceFluidMapper::SafeDownCast(actor->GetMapper()) : nullptr;
}

vtkPFBrushStrokeFluidMapper* lastStrokes(Window& w)
{
  return vtkPFBrushStrokeFluidMapper::SafeDownCast(lastMapper(w));
}

int check()
{
  Window w(480, 360);
  const double h = 0.04, r = 0.04, R = 0.8;
  auto ball = parafluid_test::latticeBall(R - r, h);
  const double surface = parafluid_test::volumeRadius(ball->GetNumberOfPoints(), h);

  // Passes that the settings switch off are not run.
  // (Particles large on screen smooth at reduced resolution: 2 more passes, down and up.)
  auto passes = [&](int method, int iterations, int mode)
  {
    show(w, ours(ball, r, method, iterations, mode));
    w.Render();
    return lastMapper(w)->GetLastPassCount() - (lastMapper(w)->GetLastSmoothingFactor() > 1 ? 2 : 0);
  };
  using M = vtkPFScreenSpaceFluidMapper;
  expect(passes(M::NarrowRange, 0, M::OpaqueSurface) == 2, "opaque, no smoothing: splats + shading only");
  expect(passes(M::NarrowRange, 3, M::OpaqueSurface) == 2 + 6, "opaque, narrow-range x3: 6 separable filter passes");
  expect(passes(M::CurvatureFlow, 10, M::OpaqueSurface) == 2 + 10, "curvature flow x10: 10 passes");
  expect(passes(M::NarrowRange, 3, M::TransparentFluid) == 2 + 6 + 3,
         "transparent: + thickness splats and 2 blur passes");
  expect(passes(M::NarrowRange, 3, M::ParticleDepth) == 2, "particle-depth display: no smoothing, no thickness");
  expect(passes(M::NarrowRange, 3, M::Toon) == 2 + 6 + 5,
         "toon: + tensor, its 2 blur passes, DoG across, average along");
  {
    double spacing = 0.0;
    auto swirl = parafluid_test::damBlock(20000, spacing);
    parafluid_test::addSwirl(swirl);
    show(w, ours(swirl, spacing, M::NarrowRange, 3, M::BrushStrokes));
    w.Render();
    std::printf("brush strokes on a swirling block: %lld strokes, %lld segments\n",
                static_cast<long long>(lastStrokes(w)->GetLastStrokeCount()),
                static_cast<long long>(lastStrokes(w)->GetLastStrokeSegmentCount()));
    expect(lastMapper(w)->GetLastPassCount() == 2 + 6 + 1,
           "brush strokes: one stroke pass over the smoothed surface, no toon line passes");
    expect(lastStrokes(w)->GetLastStrokeCount() > 100, "brush strokes: a swirling block gets strokes");
  }
  // Toon: the lit ball is flat bands of the fluid colour (plus the highlight and the lines), a
  // dark silhouette runs round it, and its smooth interior has no lines.
  {
    show(w, ours(ball, r, M::NarrowRange, 3, M::Toon));
    auto* toon = vtkPFToonFluidMapper::SafeDownCast(lastMapper(w));
    toon->SetFluidColor(0.1, 0.45, 0.75);
    w.Render();
    vtkNew<vtkUnsignedCharArray> rgb;
    w.window->GetPixelData(0, 0, w.width - 1, w.height - 1, 0, rgb);
    auto pixel = [&](int i, int j) { return rgb->GetPointer(3 * (static_cast<vtkIdType>(j) * w.width + i)); };
    const int bands = toon->GetToonBands();
    const double* base = toon->GetFluidColor();
    // Band k is the fluid colour times mix(0.35, 1, k / (bands - 1)); the highlight is 80 % white.
    auto classify = [&](const unsigned char* c)
    {
      for (int k = 0; k < bands; ++k)
      {
        const double f = 0.35 + 0.65 * k / (bands - 1);
        bool same = true;
        for (int q = 0; q < 3; ++q)
        {
          same = same && std::abs(c[q] - 255.0 * base[q] * f) <= 2.0;
        }
        if (same)
        {
          return k;
        }
      }
      return -1;
    };
    // The ball's radius on screen in pixels (view angle 30 degrees; R / distance is the tangent of
    // its half-angle to within 2 %).
    const double ballPixels = 0.5 * w.height * (R / w.distance) / std::tan(vtkMath::RadiansFromDegrees(15.0));
    std::vector<int> bandCount(bands, 0);
    int interior = 0, banded = 0, dark = 0;
    const double darkest = 255.0 * 0.35 * (0.2126 * base[0] + 0.7152 * base[1] + 0.0722 * base[2]);
    auto luminance = [](const unsigned char* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
    for (int j = 0; j < w.height; ++j)
    {
      for (int i = 0; i < w.width; ++i)
      {
        const double rho = std::hypot(i + 0.5 - 0.5 * w.width, j + 0.5 - 0.5 * w.height);
        const unsigned char* c = pixel(i, j);
        const int k = classify(c);
        if (rho < 0.9 * ballPixels && k >= 0)
        {
          ++bandCount[k]; // the lower bands lie near the rim (headlight)
        }
        if (rho > 0.7 * ballPixels)
        {
          continue;
        }
        ++interior;
        banded += k >= 0 || (c[0] > 200 && c[1] > 200) ? 1 : 0; // a band or the highlight
        dark += luminance(c) < 0.8 * darkest ? 1 : 0;
      }
    }
    const int levels =
      static_cast<int>(std::count_if(bandCount.begin(), bandCount.end(), [&](int n) { return n > interior / 200; }));
    std::printf("toon interior: %d px, %.1f %% flat bands or highlight, %d band levels, %.2f %% line pixels\n",
                interior, 100.0 * banded / interior, levels, 100.0 * dark / interior);
    expect(banded > 0.97 * interior, "toon: the ball's interior is flat bands of the fluid colour and the highlight");
    expect(levels >= 2, "toon: the lighting falls into at least two bands across the ball");
    expect(dark < 0.01 * interior, "toon: no lines inside the smooth ball");
    // The silhouette: on every row through the ball, the first fluid pixels from the left and
    // right include one darker than the darkest band.
    const unsigned char* background = pixel(0, 0);
    int rows = 0, outlined = 0;
    for (int j = static_cast<int>(0.5 * w.height - 0.6 * ballPixels); j < 0.5 * w.height + 0.6 * ballPixels; j += 4)
    {
      ++rows;
      bool left = false, right = false;
      for (int side = 0; side < 2; ++side)
      {
        int i = side == 0 ? 0 : w.width - 1;
        const int step = side == 0 ? 1 : -1;
        while (i >= 0 && i < w.width && std::equal(background, background + 3, pixel(i, j)))
        {
          i += step;
        }
        for (int k = 0; k < 5 && i >= 0 && i < w.width; ++k, i += step)
        {
          (side == 0 ? left : right) |= luminance(pixel(i, j)) < 0.8 * darkest;
        }
      }
      outlined += left && right ? 1 : 0;
    }
    std::printf("toon silhouette: outlined on %d of %d rows\n", outlined, rows);
    expect(outlined >= rows - 1, "toon: a dark silhouette line runs round the ball");

    // Depth contours every 2 particle radii: rings round the view axis. Along the middle row the
    // surface depth rises by R (1 - cos) from the centre, so the rings within 0.7 R of it are
    // those of depth R (1 - sqrt(1 - 0.49)) / (2 r) ~ 2.9 spacings: 2 or 3 crossings each side.
    toon->SetDepthContourSpacing(2.0);
    w.Render();
    w.window->GetPixelData(0, 0, w.width - 1, w.height - 1, 0, rgb);
    int crossings = 0;
    bool wasDark = false;
    for (int i = static_cast<int>(0.5 * w.width - 0.7 * ballPixels); i < 0.5 * w.width + 0.7 * ballPixels; ++i)
    {
      const bool isDark = luminance(pixel(i, w.height / 2)) < 0.8 * darkest;
      crossings += isDark && !wasDark ? 1 : 0;
      wasDark = isDark;
    }
    std::printf("toon depth contours: %d lines crossed within 0.7 R of the centre\n", crossings);
    expect(crossings >= 4 && crossings <= 7, "toon: depth contours every 2 radii cross the middle row 4 to 7 times");
  }

  // The splats are exact spheres: one particle's depth matches its sphere to float precision.
  {
    vtkNew<vtkPolyData> one;
    vtkNew<vtkPoints> p;
    p->InsertNextPoint(0.0, 0.0, 0.0);
    one->SetPoints(p);
    show(w, ours(one, 0.5, M::NarrowRange, 0, M::OpaqueSurface));
    w.Render();
    const DepthError e = w.MeasureSphere(0.5, 0.5);
    std::printf("single sphere: rms %.2e r, coverage %.3f\n", e.rms, e.coverage);
    expect(e.rms < 2e-3 && e.coverage > 0.99, "a single particle's depth is its exact sphere");
    expect(lastMapper(w)->GetLastUsedPointSprites(), "a sphere well inside the view is drawn as one point sprite");
    // Larger than the largest point sprite and past the window's edges: drawn as a quad, as exact.
    show(w, ours(one, 1.5, M::NarrowRange, 0, M::OpaqueSurface));
    w.Render();
    const DepthError big = w.MeasureSphere(1.5, 1.5);
    std::printf("sphere past the edges: rms %.2e r, coverage %.3f\n", big.rms, big.coverage);
    expect(!lastMapper(w)->GetLastUsedPointSprites(), "a sphere past the window's edges is drawn as a quad");
    expect(big.rms < 2e-3 && big.coverage > 0.99, "the quad's depth is the exact sphere too");
  }

  // Thickness is the summed chord length through the particles' spheres, at half resolution for
  // particles large on screen and at a quarter for small ones; either way a slab's thickness
  // reads back as its spheres' volume per unit area, through the Thickness display's
  // 1 - exp(-thickness / attenuation).
  for (const double spacing : { 0.05, 0.045, 0.02, 0.008 })
  {
    const int layers = 6;
    auto slab = parafluid_test::latticeSlab(0.6, layers, spacing);
    auto prop = ours(slab, spacing, M::NarrowRange, 0, M::Thickness);
    auto* mapper = static_cast<vtkPFScreenSpaceFluidMapper*>(static_cast<vtkActor*>(prop.Get())->GetMapper());
    const double expected = layers * 4.0 / 3.0 * vtkMath::Pi() * std::pow(spacing, 3) / (spacing * spacing);
    mapper->SetAttenuationDistance(expected / std::log(2.0)); // reads back as grey 0.5
    show(w, prop);
    w.Render();
    vtkNew<vtkFloatArray> rgba;
    w.window->GetRGBAPixelData(w.width / 2 - 20, w.height / 2 - 20, w.width / 2 + 20, w.height / 2 + 20, 0, rgba);
    double grey = 0.0;
    for (vtkIdType k = 0; k < rgba->GetNumberOfTuples(); ++k)
    {
      grey += rgba->GetComponent(k, 0) / rgba->GetNumberOfTuples();
    }
    const double measured = -mapper->GetAttenuationDistance() * std::log(1.0 - grey);
    const int factor = mapper->GetLastThicknessFactor();
    std::printf("slab, spacing %.3f: thickness factor %d, %.4f against %.4f\n", spacing, factor, measured, expected);
    expect(factor == (spacing > 0.047 ? 2 : 4), "thickness resolution follows the particles' size on screen");
    expect(std::abs(measured / expected - 1.0) < 0.08, "thickness is the spheres' volume per unit area (8 %)");
  }

  // Smoothing flattens the bumps of the lattice ball's splats without moving its surface: error
  // against the sphere holding the particles' volume (N h^3).
  show(w, ours(ball, r, M::NarrowRange, 0, M::OpaqueSurface));
  w.Render();
  const DepthError raw = w.MeasureSphere(surface, r);
  std::printf("raw splats: rms %.3f r, mean %.3f r, spread %.3f r\n", raw.rms, raw.mean, raw.spread);
  expect(raw.coverage > 0.99, "the raw splats cover the ball");
  const struct
  {
    int method, iterations;
    const char* name;
  } methods[] = { { M::NarrowRange, 3, "narrow-range x3" },
                  { M::Bilateral, 3, "bilateral x3" },
                  { M::CurvatureFlow, 150, "curvature flow x150" } };
  for (const auto& m : methods)
  {
    show(w, ours(ball, r, m.method, m.iterations, M::OpaqueSurface));
    w.Render();
    const DepthError e = w.MeasureSphere(surface, r);
    std::printf("%s: rms %.3f r, mean %.3f r, spread %.3f r, coverage %.3f\n", m.name, e.rms, e.mean, e.spread,
                e.coverage);
    expect(e.coverage > 0.99, std::string(m.name) + " keeps the ball covered");
    expect(e.spread < 0.7 * raw.spread, std::string(m.name) + " smooths the bumps (spread down by 30 %+)");
    // The splats (radius = spacing) stand proud of the fluid's volume; smoothing may settle them
    // a little into the dips between particles, but must not shrink or grow the ball.
    expect(std::abs(e.mean - raw.mean) < 0.3, std::string(m.name) + " keeps the ball's size (moves it < 0.3 r)");
  }

  // Zero particles, a NaN particle and a camera inside the fluid draw without GL errors.
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkPoints> none;
    empty->SetPoints(none);
    show(w, ours(empty, r, M::NarrowRange, 3, M::TransparentFluid));
    w.Render();
    vtkNew<vtkPolyData> bad;
    vtkNew<vtkPoints> p;
    p->InsertNextPoint(std::nan(""), 0.0, 0.0);
    p->InsertNextPoint(0.0, 0.0, 0.0);
    bad->SetPoints(p);
    show(w, ours(bad, 0.3, M::NarrowRange, 0, M::OpaqueSurface));
    w.Render();
    const DepthError e = w.MeasureSphere(0.3, 0.3);
    expect(e.coverage > 0.99 && e.rms < 0.05, "a NaN particle is dropped; the finite one still draws");
    show(w, ours(ball, r, M::NarrowRange, 3, M::TransparentFluid));
    w.renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 0.1);
    w.window->Render();
    w.ResetCamera();
    expect(true, "camera inside the fluid renders");
  }
  std::printf("%d failure(s)\n", failures);
  return failures == 0 ? 0 : 1;
}
}

int main(int argc, char* argv[])
{
  int width = 1280, height = 720;
  long big = 1000000;
  std::string csvPath = "fluid_render_benchmark.csv";
  std::string only; // "accuracy" (the ball), "speed" (the blocks), "big" (the big block), "npr" (toon
                    // and brush strokes against opaque on the blocks); empty: all
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--check")
    {
      return check();
    }
    if (a == "--width" && i + 1 < argc)
    {
      width = std::atoi(argv[++i]);
    }
    else if (a == "--height" && i + 1 < argc)
    {
      height = std::atoi(argv[++i]);
    }
    else if (a == "--big" && i + 1 < argc)
    {
      big = std::atol(argv[++i]);
    }
    else if (a == "--only" && i + 1 < argc)
    {
      only = argv[++i];
    }
    else if (a == "--csv" && i + 1 < argc)
    {
      csvPath = argv[++i];
    }
    else
    {
      std::fprintf(stderr,
                   "usage: %s [--check] [--width W] [--height H] [--big N] [--csv file] [--only "
                   "accuracy|speed|big|npr|raymarch|raymarch-blocks]\n",
                   argv[0]);
      return 2;
    }
  }
  std::ofstream csv(csvPath);
  csv << "scene,renderer,method,iterations,seconds_per_frame,rms_error_radii,mean_error_radii,spread_radii,coverage\n";
  Window w(width, height);
  using M = vtkPFScreenSpaceFluidMapper;

  // 1. Time against depth error on a lattice ball (spacing = radius = 0.02, ~60k particles).
  const double h = 0.02, r = 0.02, R = 0.8;
  auto ball = parafluid_test::latticeBall(R - r, h);
  const double surface = parafluid_test::volumeRadius(ball->GetNumberOfPoints(), h);
  std::printf("ball: %lld particles, %dx%d; error in particle radii against the sphere of their volume, R = %.4f\n",
              static_cast<long long>(ball->GetNumberOfPoints()), width, height, surface);
  std::printf("%-36s %6s %10s %8s %8s %8s %9s\n", "renderer / smoothing", "iters", "ms/frame", "rms", "mean", "spread",
              "coverage");
  auto row =
    [&](const char* scene, const char* who, const char* method, int iterations, double seconds, const DepthError& e)
  {
    std::printf("%-36s %6d %10.1f %8.3f %8.3f %8.3f %9.3f\n", (std::string(who) + " " + method).c_str(), iterations,
                1000.0 * seconds, e.rms, e.mean, e.spread, e.coverage);
    csv << scene << ',' << who << ',' << method << ',' << iterations << ',' << seconds << ',' << e.rms << ',' << e.mean
        << ',' << e.spread << ',' << e.coverage << '\n';
  };
  const struct
  {
    int method;
    const char* name;
    std::vector<int> iterations;
  } sweeps[] = { { M::NarrowRange, "narrow-range", { 0, 1, 2, 3, 5, 8 } },
                 { M::Bilateral, "bilateral", { 1, 2, 3, 5, 8 } },
                 { M::CurvatureFlow, "curvature-flow", { 10, 20, 40, 80, 160 } } };
  for (const auto& s : sweeps)
  {
    if (!only.empty() && only != "accuracy")
    {
      break;
    }
    for (int it : s.iterations)
    {
      show(w, ours(ball, r, s.method, it, M::OpaqueSurface));
      const double seconds = w.FrameTime(3);
      w.Render();
      row("ball", "ours", s.name, it, seconds, w.MeasureSphere(surface, r));
    }
  }
  // The peer repaired (see PeekFluidMapper), and once as shipped.
  const struct
  {
    int iterations;
    bool repaired;
  } peerRuns[] = { { 0, true }, { 1, true }, { 2, true }, { 3, true }, { 5, true }, { 8, true }, { 3, false } };
  for (const auto& run : peerRuns)
  {
    if (!only.empty() && only != "accuracy")
    {
      break;
    }
    auto volume = vtkFluid(ball, r, run.iterations, false);
    auto* peek = static_cast<PeekFluidMapper*>(static_cast<vtkVolume*>(volume.Get())->GetMapper());
    peek->Repaired = run.repaired;
    show(w, volume);
    const double seconds = w.FrameTime(3);
    w.Render();
    row("ball", "vtkOpenGLFluidMapper", run.repaired ? "narrow-range" : "narrow-range, as shipped", run.iterations,
        seconds, w.MeasureSphere(peek->SurfaceDistances(w.farPlane), surface, r));
  }

  // 2. Frame time on a dam-break block, 100k and `big` particles, transparent fluid, narrow-range
  //    x3 (vtkOpenGLFluidMapper's defaults), ours also opaque and with passes skipped.
  for (long count : { 100000L, big })
  {
    if (only == "accuracy" || only.rfind("raymarch", 0) == 0 || (only == "big" && count != big))
    {
      continue;
    }
    double spacing = 0.0;
    auto block = parafluid_test::damBlock(count, spacing);
    parafluid_test::addSwirl(block);
    const double radius = spacing; // splats overlap like a fluid renderer's usually do
    w.renderer->GetActiveCamera()->SetPosition(1.0, -2.2, 2.4);
    w.renderer->GetActiveCamera()->SetFocalPoint(1.0, 0.5, 0.3);
    w.renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
    const std::string scene = "block" + std::to_string(block->GetNumberOfPoints());
    std::printf("\n%s: %lld particles, radius %.4f, %dx%d\n", scene.c_str(),
                static_cast<long long>(block->GetNumberOfPoints()), radius, width, height);
    auto time = [&](vtkProp* prop)
    {
      show(w, prop);
      w.renderer->GetActiveCamera()->SetPosition(1.0, -2.2, 2.4);
      w.renderer->GetActiveCamera()->SetFocalPoint(1.0, 0.5, 0.3);
      w.renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
      w.nearPlane = 0.5;
      const double s = w.FrameTime(5);
      w.nearPlane = 1.0;
      return s;
    };
    const DepthError none;
    // Non-photorealistic styles against the opaque surface they build on: the toon line passes
    // and the brush-stroke pass work in image space, so their extra cost should not grow with
    // the particle count. (The stroke layout runs once per data change, in the warm-up frame.)
    row(scene.c_str(), "ours", "opaque narrow-range", 3, time(ours(block, radius, M::NarrowRange, 3, M::OpaqueSurface)),
        none);
    row(scene.c_str(), "ours", "toon narrow-range", 3, time(ours(block, radius, M::NarrowRange, 3, M::Toon)), none);
    row(scene.c_str(), "ours", "brush strokes narrow-range", 3,
        time(ours(block, radius, M::NarrowRange, 3, M::BrushStrokes)), none);
    {
      show(w, ours(block, radius, M::NarrowRange, 3, M::BrushStrokes));
      const auto start = std::chrono::steady_clock::now();
      w.Render();
      const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%-36s %6s %10.1f   (first frame: upload + %lld strokes laid out, %lld segments)\n",
                  "ours / brush strokes, first frame", "3", 1e3 * first,
                  static_cast<long long>(lastStrokes(w)->GetLastStrokeCount()),
                  static_cast<long long>(lastStrokes(w)->GetLastStrokeSegmentCount()));
      csv << scene << ",ours,brush strokes first frame,3," << first << ",,,,\n";
    }
    if (only == "npr")
    {
      continue;
    }
    row(scene.c_str(), "ours", "transparent narrow-range", 3,
        time(ours(block, radius, M::NarrowRange, 3, M::TransparentFluid)), none);
    row(scene.c_str(), "ours", "opaque unsmoothed", 0, time(ours(block, radius, M::NarrowRange, 0, M::OpaqueSurface)),
        none);
    row(scene.c_str(), "vtkOpenGLFluidMapper", "transparent narrow-range", 3, time(vtkFluid(block, radius, 3, true)),
        none);
    row(scene.c_str(), "vtkOpenGLFluidMapper", "opaque narrow-range", 3, time(vtkFluid(block, radius, 3, false)), none);
    row(scene.c_str(), "vtkPointGaussianMapper", "spheres", 0, time(gaussianSpheres(block, radius)), none);
  }

  // 3. The three ways of drawing particle water, side by side: Ray-Marched Fluid, Screen-Space
  //    Fluid and Particle Surface's mesh drawn by the Surface representation's mapper. Time
  //    against error on the ball, frame time on the blocks, and where the ray march's time goes.
  if (only.empty() || only == "raymarch" || only == "raymarch-blocks")
  {
    using RM = vtkPFRayMarchedFluidMapper;
    std::printf("\nthree ways on the ball (error in spacings against the sphere of the particles' volume)\n");
    const bool ballPart = only != "raymarch-blocks";
    for (double kernel : { 2.0, 3.0 })
    {
      for (double scale : { 1.0, 0.5 })
      {
        if (!ballPart)
        {
          break;
        }
        show(w, rayMarched(ball, h, RM::OpaqueSurface, kernel, scale));
        const double seconds = w.FrameTime(3);
        w.Render();
        const std::string method =
          "opaque, kernel " + std::to_string(kernel).substr(0, 3) + " d, scale " + std::to_string(scale).substr(0, 4);
        row("ball", "ray-marched", method.c_str(), 0, seconds, w.MeasureSphere(surface, h));
      }
    }
    if (ballPart)
    {
      show(w, ours(ball, r, M::NarrowRange, 3, M::OpaqueSurface));
      const double seconds = w.FrameTime(3);
      w.Render();
      row("ball", "screen-space", "opaque narrow-range", 3, seconds, w.MeasureSphere(surface, h));
    }
    for (double kernel : { 2.0, 3.0 })
    {
      if (!ballPart)
      {
        break;
      }
      double build = 0.0;
      show(w, meshSurface(ball, h, kernel, build));
      const double seconds = w.FrameTime(3);
      w.Render();
      const std::string method = "mesh kernel " + std::to_string(kernel).substr(0, 3) + " d (+" +
                                 std::to_string(static_cast<int>(1e3 * build)) + " ms to build)";
      row("ball", "particle-surface", method.c_str(), 10, seconds, w.MeasureSphere(surface, h));
    }
    for (long count : { 100000L, big })
    {
      double spacing = 0.0;
      auto block = parafluid_test::damBlock(count, spacing);
      parafluid_test::addSwirl(block);
      const std::string scene = "block" + std::to_string(block->GetNumberOfPoints());
      std::printf("\n%s: %lld particles, spacing %.4f, %dx%d\n", scene.c_str(),
                  static_cast<long long>(block->GetNumberOfPoints()), spacing, width, height);
      auto place = [&]()
      {
        w.renderer->GetActiveCamera()->SetPosition(1.0, -2.2, 2.4);
        w.renderer->GetActiveCamera()->SetFocalPoint(1.0, 0.5, 0.3);
        w.renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
      };
      auto time = [&](vtkProp* prop)
      {
        show(w, prop);
        place();
        w.nearPlane = 0.5;
        const double seconds = w.FrameTime(5);
        w.nearPlane = 1.0;
        return seconds;
      };
      const DepthError none;
      const double ssf = time(ours(block, spacing, M::NarrowRange, 3, M::TransparentFluid));
      row(scene.c_str(), "screen-space", "transparent narrow-range", 3, ssf, none);
      for (int mode : { RM::TransparentFluid, RM::OpaqueSurface, RM::Normals })
      {
        for (double scale : { 1.0, 0.5, 0.25 })
        {
          if (mode == RM::Normals && scale < 1.0)
          {
            break; // normals against opaque at full resolution: what the shading costs
          }
          const char* names[] = { "opaque", "transparent", "normals" };
          const double seconds = time(rayMarched(block, spacing, mode, 2.0, scale));
          const std::string method = std::string(names[mode]) + ", scale " + std::to_string(scale).substr(0, 4);
          row(scene.c_str(), "ray-marched", method.c_str(), 0, seconds, none);
          if (mode == RM::TransparentFluid && scale == 1.0)
          {
            std::printf("%-36s %17.2f x Screen-Space Fluid's transparent frame\n", "  ratio", seconds / ssf);
          }
        }
      }
      // The grid build (CPU, once per data change) and the samples per pixel.
      show(w, rayMarched(block, spacing, RM::Steps, 2.0, 1.0));
      place();
      w.nearPlane = 0.5;
      const double skipping = meanSamples(w);
      auto* mapper = static_cast<RM*>(vtkActor::SafeDownCast(w.renderer->GetViewProps()->GetLastProp())->GetMapper());
      std::printf("%-36s %10.1f ms (%lld cells, %lld may hold the surface)\n", "  grid build (sort + occupancy)",
                  mapper->GetLastBuildMilliseconds(), mapper->GetLastCellCount(), mapper->GetLastOccupiedCellCount());
      show(w, rayMarched(block, spacing, RM::Steps, 2.0, 1.0, Skip::None));
      place();
      const double brute = meanSamples(w);
      w.nearPlane = 1.0;
      std::printf("%-36s %10.2f with skipping, %.2f without (%.1fx)\n", "  samples of the field per pixel", skipping,
                  brute, brute / skipping);
      csv << scene << ",ray-marched,samples per pixel skipping," << skipping << ",,,,,\n";
      csv << scene << ",ray-marched,samples per pixel brute force," << brute << ",,,,,\n";
      // Where a transparent frame's time goes, pass by pass (the GPU finished after each).
      {
        auto prop = rayMarched(block, spacing, RM::TransparentFluid, 2.0, 1.0);
        auto* timed = static_cast<RM*>(vtkActor::SafeDownCast(prop)->GetMapper());
        timed->SetTimePasses(true);
        time(prop);
        std::printf("%-36s %10.1f ms copy of the scene, %.1f ms start/stop splats, %.1f ms march + shading\n",
                    "  transparent frame by pass", timed->GetLastPassMilliseconds(0), timed->GetLastPassMilliseconds(1),
                    timed->GetLastPassMilliseconds(2));
        csv << scene << ",ray-marched,pass copy," << timed->GetLastPassMilliseconds(0) << ",,,,,\n";
        csv << scene << ",ray-marched,pass splats," << timed->GetLastPassMilliseconds(1) << ",,,,,\n";
        csv << scene << ",ray-marched,pass march," << timed->GetLastPassMilliseconds(2) << ",,,,,\n";
      }
      // The skipping's parts, on the block and on the block with 5 % of its particles as spray
      // droplets (2 x 2 x 2 particles each, with a surface of their own) in the air above it.
      auto spray = parafluid_test::withDroplets(block, spacing, 0.05, 7);
      for (vtkPolyData* data : { block.Get(), spray.Get() })
      {
        const char* which = data == block.Get() ? "block" : "block + 5 % droplets";
        const char* names[] = { "brute force", "occupancy grid", "+ splats, one pair", "+ splats, splash apart" };
        for (Skip skip : { Skip::None, Skip::Occupancy, Skip::SplatsMerged, Skip::Splats })
        {
          if (skip == Skip::None && data == block.Get())
          {
            continue; // measured above
          }
          const double seconds = time(rayMarched(data, spacing, RM::TransparentFluid, 2.0, 1.0, skip));
          show(w, rayMarched(data, spacing, RM::Steps, 2.0, 1.0, skip));
          place();
          w.nearPlane = 0.5;
          const double samples = meanSamples(w);
          w.nearPlane = 1.0;
          std::printf("  %-22s %-24s %8.1f ms transparent, %.2f samples per pixel\n", which,
                      names[static_cast<int>(skip)], 1e3 * seconds, samples);
          csv << scene << ",ray-marched," << which << " " << names[static_cast<int>(skip)] << "," << seconds
              << ",,,,,\n";
        }
      }
      double build = 0.0;
      const double meshFrame = time(meshSurface(block, spacing, 2.0, build));
      row(scene.c_str(), "particle-surface", "mesh kernel 2 d, frame", 10, meshFrame, none);
      std::printf("%-36s %10.1f ms (marching cubes + 10 Taubin pairs, once per data change)\n", "  mesh build",
                  1e3 * build);
      csv << scene << ",particle-surface,mesh build,10," << build << ",,,,\n";
    }
  }
  std::printf("\nCSV: %s\n", csvPath.c_str());
  return 0;
}
