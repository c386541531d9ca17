#include "vtkPFBrushStrokeFluidMapper.h"

#include "FluidBrushStrokePass.h"
#include "FluidFrame.h"
#include "FluidScreenTargets.h"
#include "FluidShadePass.h"
#include "GuardedRequest.h"

#include "parafluid/npr/BrushStrokes.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkPFBrushStrokeFluidMapper);

vtkPFBrushStrokeFluidMapper::vtkPFBrushStrokeFluidMapper()
  : Strokes(new parafluid::FluidBrushStrokePass)
{
  // Toon bands under the strokes: smoothed as the Toon Fluid's (vtkPFToonFluidMapper).
  this->SetFilterSize(4.0);
  this->SetSpreadFilterTaps(false);
  this->SetSmoothSilhouettes(false);
}

vtkPFBrushStrokeFluidMapper::~vtkPFBrushStrokeFluidMapper() = default;

void vtkPFBrushStrokeFluidMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StrokeWidth: " << this->StrokeWidth << "\n";
  os << indent << "MaxStrokes: " << this->MaxStrokes << "\n";
}

void vtkPFBrushStrokeFluidMapper::PrepareStyle(vtkPointSet* input, vtkUnsignedCharArray* colors,
                                               vtkOpenGLRenderWindow* window, vtkMTimeType key)
{
  if (key != this->StrokeKey)
  {
    this->LayOutStrokes(input, colors, window);
    this->StrokeKey = key;
  }
  this->LastStrokeCount = static_cast<vtkIdType>(this->Strokes->StrokeCount());
  this->LastStrokeSegmentCount = static_cast<vtkIdType>(this->Strokes->SegmentCount());
}

void vtkPFBrushStrokeFluidMapper::FillShading(parafluid::FluidShadeSettings& shading) const
{
  this->Superclass::FillShading(shading);
  shading.DisplayMode = BrushStrokes;
}

void vtkPFBrushStrokeFluidMapper::DrawOverSurface(parafluid::FluidFrame& frame, parafluid::FluidScreenTargets& targets,
                                                  int depth)
{
  if (this->Strokes->SegmentCount() == 0)
  {
    return;
  }
  parafluid::FluidBrushStrokePass::View view{ frame.ModelView,
                                              frame.Projection,
                                              { frame.Size[0], frame.Size[1] },
                                              { frame.Origin[0], frame.Origin[1] },
                                              { frame.RectMin[0], frame.RectMin[1] },
                                              { frame.RectMax[0], frame.RectMax[1] },
                                              frame.Parallel,
                                              { frame.ProjectionCoefficients[0], frame.ProjectionCoefficients[1],
                                                frame.ProjectionCoefficients[2], frame.ProjectionCoefficients[3] } };
  frame.State->vtkglDepthMask(GL_FALSE); // the surface's depth is written already
  // A stroke more than 3 particle radii behind the surface runs through hidden water.
  if (!this->Strokes->Draw(frame.Window, view, targets.Depth[depth], targets.EmptyVAO, this->StrokeWidth,
                           3.0 * frame.MaxRadius))
  {
    vtkErrorMacro("The brush-stroke shader did not compile (see the messages above).");
  }
  frame.State->vtkglDepthMask(GL_TRUE);
  ++frame.PassCount;
}

void vtkPFBrushStrokeFluidMapper::ReleaseStyle(vtkWindow* window)
{
  this->Superclass::ReleaseStyle(window);
  this->Strokes->Release(window);
  this->StrokeKey = 0;
}

void vtkPFBrushStrokeFluidMapper::SetStrokeVelocityArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->StrokeVelocityArray)
  {
    this->StrokeVelocityArray = value;
    this->Modified();
  }
}

void vtkPFBrushStrokeFluidMapper::SetStrokeColorArray(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->StrokeColorArray)
  {
    this->StrokeColorArray = value;
    this->Modified();
  }
}

void vtkPFBrushStrokeFluidMapper::LayOutStrokes(vtkPointSet* input, vtkUnsignedCharArray* colors,
                                                vtkOpenGLRenderWindow* window)
{
  // The finite particles, and where each came from.
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* velocities = input->GetPointData()->GetArray(this->StrokeVelocityArray.c_str());
  if (velocities && velocities->GetNumberOfComponents() != 3)
  {
    velocities = nullptr;
  }
  if (!velocities)
  {
    vtkWarningMacro("Brush strokes: no 3-component point array '"
                    << this->StrokeVelocityArray << "'; the water is taken as still (fixed strokes only).");
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
  parameters.flow.kernelRadius = 4.0 * this->GetUploadedMaxRadius();
  parameters.flow.seedStride = this->StrokeSeedStride;
  parameters.flow.pointsPerLine = 12;
  parameters.flow.lineDuration = this->StrokeDuration;
  parameters.flow.maxLines = static_cast<std::size_t>(this->MaxStrokes);
  parameters.strokeLength = this->StrokeLength * this->GetUploadedMaxRadius();
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
    vtkErrorMacro("Brush strokes: " << parafluid::vtk::exceptionText(e));
  }
  // Colours: the scalar colouring, else the colour array from dark to light fluid colour.
  const double* fluidColor = this->GetFluidColor();
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
        const double dark = 0.6 * fluidColor[k], light = fluidColor[k] + 0.6 * (1.0 - fluidColor[k]);
        rgb[3 * s + k] = static_cast<float>(dark + t * (light - dark));
      }
    }
  }
  this->Strokes->Upload(window, strokes, rgb);
}
