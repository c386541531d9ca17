/**
 * @class vtkPFRainMapper
 * @brief Draws rain drops as streaks lit by precomputed radiance transfer, or impacts as splash
 * sprites (Kind), over the scene.
 *
 * Streaks read the point arrays `diameter` [m], `velocity` [m/s] and `streak_length` [m] (the Rain
 * filter's drops; a drop without them is 2 mm wide, falls at 6 m/s and streaks over 1/60 s).
 * Splashes read `age` [s], `normal`, `slope` [deg], `impact_angle` [deg] and `on_water` (the Rain
 * filter's splashes). The environment is six cube-map images when set, else the view's background.
 * Drawn by a vtkPFScreenSpaceFluidActor (after the rest of the scene), with the scene's depth.
 */
#pragma once

#include "FluidSharedScene.h" // SharedRendering member
#include "ParaFluidRainRepresentationsModule.h"
#include "SetParameterMacros.h"
#include "vtkMapper.h"

#include <algorithm>
#include <memory>
#include <string>

class PARAFLUIDRAINREPRESENTATIONS_EXPORT vtkPFRainMapper : public vtkMapper
{
public:
  static vtkPFRainMapper* New();
  vtkTypeMacro(vtkPFRainMapper, vtkMapper);

  enum Kinds
  {
    Streaks = 0,
    Splashes = 1
  };
  vtkPFSetClampMacro(Kind, int, 0, 1);
  vtkGetMacro(Kind, int);
  /// Streaks: 0 blended streaks, 1 opaque quads of the radiance alone.
  vtkPFSetClampMacro(DisplayMode, int, 0, 1);
  vtkPFSetClampMacro(RefractiveIndex, double, 1.01, 3.0);
  vtkPFSetClampMacro(Brightness, double, 0.0, 1e6);
  vtkPFSetClampMacro(Opacity, double, 0.0, 1.0);
  vtkPFSetClampMacro(FogDistance, double, 0.0, 1e9);
  vtkPFSetClampMacro(WidthScale, double, 0.0, 1e6);
  vtkPFSetClampMacro(SplashSize, double, 0.0, 1e6);
  vtkPFSetClampMacro(SplashLifetime, double, 1e-6, 1e6);
  /// Who draws the streaks: the GPU (a triangle per drop) or the CPU (StreakRaster, one textured
  /// quad over the scene). Automatic: the CPU under a software OpenGL (llvmpipe), where it is
  /// several times faster, else the GPU.
  enum Rasterisers
  {
    AutomaticRasteriser = 0,
    GpuRasteriser = 1,
    CpuRasteriser = 2
  };
  vtkPFSetClampMacro(Rasteriser, int, 0, 2);
  vtkGetMacro(Rasteriser, int);
  /// Whether the last frame's streaks were drawn on the CPU.
  bool GetLastDrawnOnCpu() const;
  void SetEnvironmentImage(int face, const char* file);
  /// The view's background, bottom and top (the same colour twice when not a gradient), that lights
  /// the drops without environment images. Set by the representation before each render: while
  /// ParaView's processes render for compositing, their renderers' background is black.
  /// The processes sharing this frame's rendering (none: one process renders it). Shared, process 0
  /// holds the drops and takes the whole frame over (parafluid::SharedFrameTakeOver) before it
  /// draws; Render is then collective. Set by the representation every render.
  void SetSharedRendering(const parafluid::SharedRendering& sharing) { this->Sharing = sharing; }
  void SetViewBackground(const double bottom[3], const double top[3])
  {
    std::copy(bottom, bottom + 3, this->ViewBackground[0]);
    std::copy(top, top + 3, this->ViewBackground[1]);
  }

  void Render(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  double* GetBounds() override;
  using vtkMapper::GetBounds;

protected:
  vtkPFRainMapper();
  ~vtkPFRainMapper() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  parafluid::SharedRendering Sharing;
  double ViewBackground[2][3] = { { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 } };
  vtkPFRainMapper(const vtkPFRainMapper&) = delete;
  void operator=(const vtkPFRainMapper&) = delete;

  int Kind = Streaks;
  int DisplayMode = 0;
  double RefractiveIndex = 1.333;
  double Brightness = 1.0;
  double Opacity = 0.6;
  double FogDistance = 0.0;
  double WidthScale = 1.0;
  double SplashSize = 0.05;
  double SplashLifetime = 0.1;
  int Rasteriser = AutomaticRasteriser;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};
