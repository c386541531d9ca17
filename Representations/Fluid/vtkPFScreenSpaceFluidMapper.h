/**
 * @class vtkPFScreenSpaceFluidMapper
 * @brief Draws particles as a smooth liquid surface in screen space, on the GPU.
 *
 * Render is a sequencer of pass classes, in this order; each GPU pass covers only the part of the
 * viewport the fluid covers (its bounds projected, plus the filters' margin), and none runs that
 * the settings do not need:
 *  1. FluidParticleBuffers: the particles to the GPU when they changed;
 *  2. FluidFootprint: where the fluid lands on screen (CPU), and whether point sprites are safe;
 *  3. FluidScreenTargets: the targets, and a copy of the opaque scene drawn so far;
 *  4. FluidSplatPass: every particle an exact ray-traced sphere, writing the eye-space distance of
 *     the nearest surface (and the particle colour when colouring by an array); for transparent
 *     fluid and the thickness display also the additive chord lengths at reduced resolution;
 *  5. FluidThicknessBlurPass: that thickness blurred by a separable Gaussian;
 *  6. FluidDepthSmoothingPass: the depth smoothed SmoothingIterations times: the narrow-range
 *     filter (Truong & Yuksel 2018) or the bilateral filter as separable pairs of 1D passes, or
 *     screen-space curvature flow (van der Laan et al. 2009), one pass per step;
 *  7. the style's offscreen passes (RunStylePasses; the toon lines of vtkPFToonFluidMapper);
 *  8. FluidShadePass, into the view: normals from the smoothed depth, Fresnel reflection of the
 *     environment, refraction of the opaque scene behind with Beer-Lambert attenuation, specular
 *     from the renderer's lights (or a style's toon bands and lines), and the surface's depth so it
 *     composites with the scene;
 *  9. the style's drawing over the surface (DrawOverSurface; the strokes of
 *     vtkPFBrushStrokeFluidMapper).
 *
 * Styles (Representations/NPR) derive from this class and fill its protected hooks; they reuse
 * every pass above.
 *
 * The opaque scene must have been drawn first: use it with vtkPFScreenSpaceFluidActor, which
 * renders it after all opaque, translucent and volumetric geometry.
 */
#pragma once

#include "FluidSharedScene.h" // SharedRendering member
#include "ParaFluidFluidRepresentationsModule.h"
#include "SetParameterMacros.h"
#include "vtkMapper.h"

#include <memory>

#include <string>

class vtkOpenGLRenderWindow;
class vtkPointSet;
class vtkTexture;
class vtkUnsignedCharArray;
namespace parafluid
{
struct FluidFrame;
struct FluidShadeSettings;
class FluidScreenTargets;
}

class PARAFLUIDFLUIDREPRESENTATIONS_EXPORT vtkPFScreenSpaceFluidMapper : public vtkMapper
{
public:
  static vtkPFScreenSpaceFluidMapper* New();
  vtkTypeMacro(vtkPFScreenSpaceFluidMapper, vtkMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SmoothingMethods
  {
    NarrowRange = 0,
    Bilateral = 1,
    CurvatureFlow = 2
  };
  enum DisplayModes
  {
    OpaqueSurface = 0,
    TransparentFluid = 1,
    Normals = 2,
    Thickness = 3,
    ParticleDepth = 4,
    // The shading of the styles in Representations/NPR (vtkPFToonFluidMapper,
    // vtkPFBrushStrokeFluidMapper); not a display mode of this class.
    Toon = 5,
    BrushStrokes = 6
  };

  //@{
  /// Particle radius in world units (when RadiusArray is empty or missing).
  vtkPFSetClampMacro(ParticleRadius, double, 1e-12, 1e30);
  vtkGetMacro(ParticleRadius, double);
  /// Point array holding each particle's radius [world units]; empty: ParticleRadius for all.
  void SetRadiusArray(const char* name);
  const char* GetRadiusArray() const { return this->RadiusArray.c_str(); }
  //@}

  //@{
  /// Depth smoothing: method, iterations (0: none), filter width in particle radii at any zoom
  /// (narrow-range and bilateral; at most MaxFilterRadius taps each side, spread out a trous when
  /// the width needs more; gaps between splats narrower than the taps fill in), the depth band in particle radii
  /// (narrow-range mu, bilateral sigma, curvature-flow boundary), and the curvature-flow step as
  /// a fraction of the explicit scheme's stability limit (below 1).
  vtkPFSetClampMacro(SmoothingMethod, int, 0, 2);
  vtkGetMacro(SmoothingMethod, int);
  vtkPFSetClampMacro(SmoothingIterations, int, 0, 1000);
  vtkGetMacro(SmoothingIterations, int);
  vtkPFSetClampMacro(FilterSize, double, 0.1, 50.0);
  vtkGetMacro(FilterSize, double);
  vtkPFSetClampMacro(MaxFilterRadius, int, 1, 64);
  vtkGetMacro(MaxFilterRadius, int);
  /// Whether the filters' taps spread out (a trous) when their width needs more than
  /// MaxFilterRadius of them (default), so the smoothing follows the particles at any zoom; off,
  /// the width is cut at MaxFilterRadius pixels (the toon and brush-stroke styles keep this look).
  vtkSetMacro(SpreadFilterTaps, bool);
  vtkGetMacro(SpreadFilterTaps, bool);
  /// Whether the silhouette is smoothed over half a particle radius (default; only when the depth
  /// is smoothed) instead of showing each particle's disc (the toon and brush-stroke styles keep
  /// the discs).
  vtkSetMacro(SmoothSilhouettes, bool);
  vtkGetMacro(SmoothSilhouettes, bool);
  vtkPFSetClampMacro(DepthRange, double, 0.01, 100.0);
  vtkGetMacro(DepthRange, double);
  vtkPFSetClampMacro(CurvatureFlowStep, double, 0.001, 0.95);
  vtkGetMacro(CurvatureFlowStep, double);
  //@}

  //@{
  /// What is drawn: see DisplayModes (OpaqueSurface to ParticleDepth).
  vtkPFSetClampMacro(DisplayMode, int, 0, 4);
  vtkGetMacro(DisplayMode, int);
  /// Colour of the fluid (opaque surface), and the tint white light takes through
  /// AttenuationDistance world units of it (transparent fluid, Beer-Lambert).
  vtkPFSetFiniteVector3Macro(FluidColor, double);
  vtkGetVector3Macro(FluidColor, double);
  vtkPFSetClampMacro(AttenuationDistance, double, 1e-12, 1e30);
  vtkGetMacro(AttenuationDistance, double);
  /// Index of refraction (1.33 for water): sets Schlick's R0.
  vtkPFSetClampMacro(RefractiveIndex, double, 1.0, 4.0);
  vtkGetMacro(RefractiveIndex, double);
  /// How far the scene behind shifts: world units per unit of normal x thickness.
  vtkPFSetClampMacro(RefractionStrength, double, 0.0, 10.0);
  vtkGetMacro(RefractionStrength, double);
  vtkPFSetClampMacro(Shininess, double, 1.0, 10000.0);
  vtkGetMacro(Shininess, double);
  vtkPFSetClampMacro(SpecularStrength, double, 0.0, 10.0);
  vtkGetMacro(SpecularStrength, double);
  vtkPFSetClampMacro(Ambient, double, 0.0, 1.0);
  vtkGetMacro(Ambient, double);
  /// Weight of the colour mapped from the scalars (ScalarVisibility) against FluidColor.
  vtkPFSetClampMacro(ColorMix, double, 0.0, 1.0);
  vtkGetMacro(ColorMix, double);
  /// A cube map (vtkTexture with CubeMap on) to reflect; without it the renderer's environment
  /// texture when it has one, else the view's background colours.
  void SetEnvironmentTexture(vtkTexture* texture);
  //@}

  void Render(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  double* GetBounds() override;

  /// The processes that share this view's rendering (pvserver or pvbatch under MPI, composited by
  /// IceT), or null when one process renders it. Shared, process 0 holds the particles and draws
  /// the fluid over every process's opaque scene (parafluid::FluidSharedScene); the others draw no
  /// fluid and lend their scene. Render is then collective. Set by the representation every render.
  void SetSharedRendering(const parafluid::SharedRendering& sharing) { this->Sharing = sharing; }
  void GetBounds(double bounds[6]) override { this->vtkMapper::GetBounds(bounds); }

  //@{
  /// What the last Render did, for tests and benchmarks: GPU passes run (splats, filters,
  /// shading), the screen rectangle they covered (x0, y0, x1, y1 in viewport pixels), and how
  /// the splats were drawn.
  int GetLastPassCount() const { return this->LastPassCount; }
  /// The reduction each way of the last narrow-range smoothing (1: at full resolution; more when
  /// the particles were so large on screen that the filter ran at reduced resolution).
  int GetLastSmoothingFactor() const { return this->LastSmoothingFactor; }
  const int* GetLastScreenRect() const { return this->LastScreenRect; }
  /// Whether the splats were drawn as one point sprite per particle (true) or as six-vertex
  /// quads (when a sphere's centre is off screen or its box exceeds the largest point size).
  bool GetLastUsedPointSprites() const { return this->LastUsedPointSprites; }
  /// Full-resolution pixels per thickness pixel, each way (2 or 4; 0 when no thickness was drawn).
  int GetLastThicknessFactor() const { return this->LastThicknessFactor; }
  //@}

protected:
  vtkPFScreenSpaceFluidMapper();
  ~vtkPFScreenSpaceFluidMapper() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  //@{
  /// Hooks of the styles built on this mapper (Representations/NPR); by default they do nothing.
  /// After the particles were uploaded (`key`: what their upload followed, an MTime).
  virtual void PrepareStyle(vtkPointSet* input, vtkUnsignedCharArray* colors, vtkOpenGLRenderWindow* window,
                            vtkMTimeType key);
  /// Whether the style's passes need the structure-tensor and line targets.
  virtual bool StyleNeedsLines() const { return false; }
  /// Offscreen passes after the depth smoothing; the smoothed depth is targets.Depth[depth].
  virtual void RunStylePasses(parafluid::FluidFrame& frame, parafluid::FluidScreenTargets& targets, int depth);
  /// The shading pass's settings (the base fills the fluid's own).
  virtual void FillShading(parafluid::FluidShadeSettings& shading) const;
  /// Drawing into the view after the shading, on the fluid's surface (its depth is written).
  virtual void DrawOverSurface(parafluid::FluidFrame& frame, parafluid::FluidScreenTargets& targets, int depth);
  virtual void ReleaseStyle(vtkWindow* window);
  /// Largest radius of the particles uploaded last [world units].
  double GetUploadedMaxRadius() const;
  //@}

  /// The camera and where the fluid lands on screen into `frame`: the particle centres' `bounds`
  /// grown by `reach` [world units], plus `margin` pixels. False when it is not on screen.
  bool PlaceOnScreen(vtkRenderer* renderer, vtkActor* actor, parafluid::FluidFrame& frame, const double bounds[6],
                     double reach, int margin);
  /// The processes sharing this frame's rendering (see SetSharedRendering), or null.
  const parafluid::SharedRendering& GetSharedRendering() const { return this->Sharing; }
  /// The cube map set by SetEnvironmentTexture (null when none).
  vtkTexture* GetEnvironmentTexture() const;
  /// The fluid's colour mapped from the scalars (null when not colouring or not one per point).
  vtkUnsignedCharArray* MapParticleColors(vtkPointSet* input);

private:
  vtkPFScreenSpaceFluidMapper(const vtkPFScreenSpaceFluidMapper&) = delete;
  void operator=(const vtkPFScreenSpaceFluidMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  double ParticleRadius = 0.01;
  parafluid::SharedRendering Sharing;
  std::string RadiusArray;
  // Render's parts. The particles to the GPU when they changed; false when none can be drawn.
  bool UploadParticles(vtkPointSet* input, vtkOpenGLRenderWindow* window);
  // Full-resolution pixels per thickness pixel, each way: 2, or 4 for particles small on screen.
  int ChooseThicknessFactor(const parafluid::FluidFrame& frame) const;
  int SmoothingMethod = NarrowRange;
  int SmoothingIterations = 3;
  double FilterSize = 2.0;
  int MaxFilterRadius = 12;
  bool SpreadFilterTaps = true;
  bool SmoothSilhouettes = true;
  double DepthRange = 2.0;
  double CurvatureFlowStep = 0.8;
  int DisplayMode = TransparentFluid;
  double FluidColor[3] = { 0.1, 0.45, 0.75 };
  double AttenuationDistance = 1.0;
  double RefractiveIndex = 1.33;
  double RefractionStrength = 0.1;
  double Shininess = 150.0;
  double SpecularStrength = 0.8;
  double Ambient = 0.2;
  double ColorMix = 0.8;
  int LastPassCount = 0;
  int LastSmoothingFactor = 1;
  int LastScreenRect[4] = { 0, 0, 0, 0 };
  bool LastUsedPointSprites = false;
  int LastThicknessFactor = 0;
};
