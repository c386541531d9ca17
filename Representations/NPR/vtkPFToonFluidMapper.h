/**
 * @class vtkPFToonFluidMapper
 * @brief The screen-space fluid drawn as an illustration: flat bands of light and ink lines.
 *
 * All of vtkPFScreenSpaceFluidMapper's passes (splats, smoothing, shading), with the lighting
 * quantised into ToonBands bands of FluidColor (35 % to full brightness, a hard highlight) and
 * lines of LineColor where the depth steps by about DepthRange particle radii or more and at
 * silhouettes, found by a flow-guided difference of Gaussians (Kang, Lee & Chui 2007) of width
 * LineWidth pixels and drawn where its response passes LineThreshold (in DepthRange units:
 * larger, fewer lines). With DepthContourSpacing > 0, also contour lines of the depth every that
 * many particle radii. The line passes (FluidToonLinePass) run only here.
 */
#pragma once

#include "ParaFluidNPRRepresentationsModule.h"
#include "SetParameterMacros.h"
#include "vtkPFScreenSpaceFluidMapper.h"

#include <memory>

namespace parafluid
{
class FluidToonLinePass;
}

class PARAFLUIDNPRREPRESENTATIONS_EXPORT vtkPFToonFluidMapper : public vtkPFScreenSpaceFluidMapper
{
public:
  static vtkPFToonFluidMapper* New();
  vtkTypeMacro(vtkPFToonFluidMapper, vtkPFScreenSpaceFluidMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Brightness levels of the fluid colour.
  vtkPFSetClampMacro(ToonBands, int, 2, 16);
  vtkGetMacro(ToonBands, int);
  vtkPFSetFiniteVector3Macro(LineColor, double);
  vtkGetVector3Macro(LineColor, double);
  /// [pixels]
  vtkPFSetClampMacro(LineWidth, double, 0.5, 8.0);
  vtkGetMacro(LineWidth, double);
  vtkPFSetClampMacro(LineThreshold, double, 0.001, 10.0);
  vtkGetMacro(LineThreshold, double);
  /// Depth contour lines every this many particle radii; 0: none.
  vtkPFSetClampMacro(DepthContourSpacing, double, 0.0, 1000.0);
  vtkGetMacro(DepthContourSpacing, double);

protected:
  vtkPFToonFluidMapper();
  ~vtkPFToonFluidMapper() override;

  bool StyleNeedsLines() const override { return true; }
  void RunStylePasses(parafluid::FluidFrame& frame, parafluid::FluidScreenTargets& targets, int depth) override;
  void FillShading(parafluid::FluidShadeSettings& shading) const override;
  void ReleaseStyle(vtkWindow* window) override;

private:
  vtkPFToonFluidMapper(const vtkPFToonFluidMapper&) = delete;
  void operator=(const vtkPFToonFluidMapper&) = delete;

  std::unique_ptr<parafluid::FluidToonLinePass> Lines;
  int ToonBands = 4;
  double LineColor[3] = { 0.02, 0.06, 0.15 };
  double LineWidth = 1.0;
  double LineThreshold = 0.1;
  double DepthContourSpacing = 0.0;
};
