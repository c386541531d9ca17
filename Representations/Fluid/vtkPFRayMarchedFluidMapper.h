/**
 * @class vtkPFRayMarchedFluidMapper
 * @brief Draws particles as a liquid by marching rays through their continuous density field.
 *
 * The field is Particle Surface's covered-volume fraction phi = d^3 sum W(|x - x_j|) (poly6 of
 * support KernelRadius x d, d the particle spacing), and the surface is phi = IsoValue, so the
 * ray-marched surface and the marching-cubes mesh of the same settings are the same surface.
 * Render is a sequencer of passes:
 *  1. RayMarchBuffers: the particles sorted into kernel-wide cells, with a conservative occupancy
 *     map of cells and blocks (Filters/Surface/Core DensityCellGrid), to the GPU when they changed;
 *  2. where the fluid lands on screen (FluidFootprint), and a copy of the opaque scene drawn so far;
 *  3. RayMarchBoundsPass (with EmptySpaceSkipping and StartStopSplats): the particles near the
 *     surface splatted as kernel-radius spheres onto a coarse target that keeps, per pixel, their
 *     nearest and farthest depth, for splash and bulk apart (Xiao et al. 2017);
 *  4. RayMarchPass: per pixel, a ray through the fluid's rectangle, between those depths, that strides over empty
 * blocks and cells, samples phi in small steps (StepSize particle spacings) only where it can reach the iso value,
 * refines the crossing, and shades it (normals from phi's analytic gradient, Fresnel reflection; for transparent fluid
 * Snell refraction, the path inside the fluid to its exit and Beer-Lambert absorption along it); at ResolutionScale < 1
 * into a reduced target that a depth-aware upsampling pass draws into the view. The fluid writes its surface's depth,
 * so it composites with the opaque scene from any camera.
 *
 * It shares the Screen-Space Fluid mapper's appearance settings (FluidColor, AttenuationDistance,
 * RefractiveIndex, Shininess, SpecularStrength, Ambient, ColorMix, EnvironmentTexture, colouring
 * by scalars), and is drawn, like it, by a vtkPFScreenSpaceFluidActor after the opaque scene.
 */
#pragma once

#include "ParaFluidFluidRepresentationsModule.h"
#include "vtkPFScreenSpaceFluidMapper.h"

#include <memory>

class PARAFLUIDFLUIDREPRESENTATIONS_EXPORT vtkPFRayMarchedFluidMapper : public vtkPFScreenSpaceFluidMapper
{
public:
  static vtkPFRayMarchedFluidMapper* New();
  vtkTypeMacro(vtkPFRayMarchedFluidMapper, vtkPFScreenSpaceFluidMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What is drawn (set through SetDisplayMode).
  enum DisplayModes
  {
    OpaqueSurface = 0,
    TransparentFluid = 1,
    Normals = 2,
    /// Colour = samples of phi per pixel: red one level per sample (up to 255), green brighter up
    /// to 64 samples; pixels no ray sampled stay empty.
    Steps = 3
  };

  //@{
  /// Particle spacing d [world units]; 0: ParticleRadius / 0.6 (the representation's automatic
  /// radius is 0.6 d).
  vtkPFSetClampMacro(ParticleSpacing, double, 0.0, 1e30);
  vtkGetMacro(ParticleSpacing, double);
  /// Support radius of the poly6 kernel, in particle spacings.
  vtkPFSetClampMacro(KernelRadius, double, 1.0, 10.0);
  vtkGetMacro(KernelRadius, double);
  /// The level of phi the surface passes through (0.5: the particles' own volume).
  vtkPFSetClampMacro(IsoValue, double, 0.001, 0.999);
  vtkGetMacro(IsoValue, double);
  /// Length of a march step near the fluid, in particle spacings.
  vtkPFSetClampMacro(StepSize, double, 0.05, 4.0);
  vtkGetMacro(StepSize, double);
  /// Most samples of phi per ray segment (to the surface, and through the fluid).
  vtkPFSetClampMacro(MaxSteps, int, 1, 4096);
  vtkGetMacro(MaxSteps, int);
  /// Pixels marched per viewport pixel, each way: 1, 0.5 or 0.25 (rounded down to one of them).
  vtkPFSetClampMacro(ResolutionScale, double, 0.25, 1.0);
  vtkGetMacro(ResolutionScale, double);
  /// Stride over cells and blocks where phi cannot reach the iso value (off: the brute-force
  /// march, for comparison).
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkBooleanMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  /// With EmptySpaceSkipping: start and stop each ray at the nearest and farthest depth of the
  /// kernel spheres of the particles over its pixel (a splat pass), splash and bulk apart.
  vtkSetMacro(StartStopSplats, bool);
  vtkBooleanMacro(StartStopSplats, bool);
  vtkGetMacro(StartStopSplats, bool);
  /// Separate start/stop depths for splash and bulk particles (off: one pair for all; for
  /// comparison).
  vtkSetMacro(SeparateSplash, bool);
  vtkBooleanMacro(SeparateSplash, bool);
  vtkGetMacro(SeparateSplash, bool);
  /// Finish the GPU's work after each pass and time it (GetLastPassMilliseconds; for benchmarks:
  /// it stalls the pipeline).
  vtkSetMacro(TimePasses, bool);
  vtkGetMacro(TimePasses, bool);
  //@}

  void Render(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkMapper::GetBounds(bounds); }

  //@{
  /// What the last Render did: the spacing used [world units], grid cells and how many may hold
  /// the surface, and the CPU time of the last grid rebuild [ms].
  double GetLastSpacing() const { return this->LastSpacing; }
  long long GetLastCellCount() const;
  long long GetLastOccupiedCellCount() const;
  double GetLastBuildMilliseconds() const;
  /// Particles of the last grid in the splash class, and those never splatted (their field cannot
  /// reach the iso value).
  long long GetLastSplashCount() const;
  long long GetLastUnsplattedCount() const;
  /// With TimePasses: wall time of the last frame's passes [ms]: 0 copy of the opaque scene,
  /// 1 start/stop splats, 2 march and shading (with the upsampling).
  double GetLastPassMilliseconds(int pass) const { return pass >= 0 && pass < 3 ? this->PassMilliseconds[pass] : 0.0; }
  //@}

protected:
  vtkPFRayMarchedFluidMapper();
  ~vtkPFRayMarchedFluidMapper() override;

private:
  vtkPFRayMarchedFluidMapper(const vtkPFRayMarchedFluidMapper&) = delete;
  void operator=(const vtkPFRayMarchedFluidMapper&) = delete;

  double EffectiveSpacing();

  struct Internals;
  std::unique_ptr<Internals> March;
  double ParticleSpacing = 0.0;
  double KernelRadius = 2.0;
  double IsoValue = 0.5;
  double StepSize = 0.5;
  int MaxSteps = 256;
  double ResolutionScale = 1.0;
  bool EmptySpaceSkipping = true;
  bool StartStopSplats = true;
  bool SeparateSplash = true;
  bool TimePasses = false;
  double LastSpacing = 0.0;
  double PassMilliseconds[3] = { 0, 0, 0 };
};
