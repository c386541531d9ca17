/**
 * @class vtkPFBrushStrokeFluidMapper
 * @brief The screen-space fluid in toon bands, painted over with brush strokes along the flow.
 *
 * vtkPFToonFluidMapper's bands without its lines, and strokes StrokeWidth pixels wide laid out by
 * parafluid::npr::layoutBrushStrokes: flow lines from every StrokeSeedStride-th particle
 * integrated over StrokeDuration seconds through StrokeVelocityArray, kept where at least
 * StrokeLength particle radii long, and strokes of that fixed length filling the slower water, at
 * most MaxStrokes. A stroke takes its seed particle's colour: the scalar colouring when on, else
 * StrokeColorArray (e.g. density) from dark to light FluidColor over its range, else FluidColor.
 * Strokes are kept to the fluid's footprint and its visible surface (FluidBrushStrokePass). The
 * layout runs on the CPU when the data or a stroke setting changes, not per frame.
 */
#pragma once

#include "ParaFluidNPRRepresentationsModule.h"
#include "SetParameterMacros.h"
#include "vtkPFToonFluidMapper.h"

#include "ParticleContract.h"

#include <memory>
#include <string>

namespace parafluid
{
class FluidBrushStrokePass;
}

class PARAFLUIDNPRREPRESENTATIONS_EXPORT vtkPFBrushStrokeFluidMapper : public vtkPFToonFluidMapper
{
public:
  static vtkPFBrushStrokeFluidMapper* New();
  vtkTypeMacro(vtkPFBrushStrokeFluidMapper, vtkPFToonFluidMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// [pixels]
  vtkPFSetClampMacro(StrokeWidth, double, 1.0, 64.0);
  vtkGetMacro(StrokeWidth, double);
  /// [particle radii]
  vtkPFSetClampMacro(StrokeLength, double, 0.5, 1000.0);
  vtkGetMacro(StrokeLength, double);
  vtkPFSetClampMacro(StrokeSeedStride, int, 1, 1000000);
  vtkGetMacro(StrokeSeedStride, int);
  /// [s] of flow integrated along each flow stroke.
  vtkPFSetClampMacro(StrokeDuration, double, 1e-6, 1e6);
  vtkGetMacro(StrokeDuration, double);
  vtkPFSetClampMacro(MaxStrokes, int, 1, 10000000);
  vtkGetMacro(MaxStrokes, int);
  void SetStrokeVelocityArray(const char* name);
  const char* GetStrokeVelocityArray() const { return this->StrokeVelocityArray.c_str(); }
  void SetStrokeColorArray(const char* name);
  const char* GetStrokeColorArray() const { return this->StrokeColorArray.c_str(); }
  /// Strokes laid out for the last drawn data, and their segments.
  vtkIdType GetLastStrokeCount() const { return this->LastStrokeCount; }
  vtkIdType GetLastStrokeSegmentCount() const { return this->LastStrokeSegmentCount; }

protected:
  vtkPFBrushStrokeFluidMapper();
  ~vtkPFBrushStrokeFluidMapper() override;

  void PrepareStyle(vtkPointSet* input, vtkUnsignedCharArray* colors, vtkOpenGLRenderWindow* window,
                    vtkMTimeType key) override;
  bool StyleNeedsLines() const override { return false; }
  void RunStylePasses(parafluid::FluidFrame&, parafluid::FluidScreenTargets&, int) override {}
  void FillShading(parafluid::FluidShadeSettings& shading) const override;
  void DrawOverSurface(parafluid::FluidFrame& frame, parafluid::FluidScreenTargets& targets, int depth) override;
  void ReleaseStyle(vtkWindow* window) override;

private:
  vtkPFBrushStrokeFluidMapper(const vtkPFBrushStrokeFluidMapper&) = delete;
  void operator=(const vtkPFBrushStrokeFluidMapper&) = delete;

  /// Lays the strokes out for `input` and uploads them.
  void LayOutStrokes(vtkPointSet* input, vtkUnsignedCharArray* colors, vtkOpenGLRenderWindow* window);

  std::unique_ptr<parafluid::FluidBrushStrokePass> Strokes;
  vtkMTimeType StrokeKey = 0; // what the strokes were laid out for
  double StrokeWidth = 6.0;
  double StrokeLength = 6.0;
  int StrokeSeedStride = 3;
  double StrokeDuration = 0.3;
  int MaxStrokes = 4000;
  std::string StrokeVelocityArray = parafluid::contract::Velocity;
  std::string StrokeColorArray = parafluid::contract::Density;
  vtkIdType LastStrokeCount = 0;
  vtkIdType LastStrokeSegmentCount = 0;
};
