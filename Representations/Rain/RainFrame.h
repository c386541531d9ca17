#pragma once
// What the rain's passes need of the frame being drawn.
#include "vtkMatrix4x4.h"
#include "vtkSmartPointer.h"

#include <array>

class vtkOpenGLRenderWindow;
class vtkOpenGLState;

namespace parafluid
{
struct RainFrame
{
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkOpenGLState* State = nullptr;
  vtkSmartPointer<vtkMatrix4x4> WorldToView; // transposed for vtkUniforms (row-major upload)
  vtkSmartPointer<vtkMatrix4x4> ViewToClip;  // transposed likewise
  float Viewport[2] = { 1.0f, 1.0f };        // pixels
  int Origin[2] = { 0, 0 };                  // the viewport's lower left corner in the framebuffer
  float Eye[3] = { 0.0f, 0.0f, 0.0f };       // camera position, world
  std::array<float, 48> Environment{};       // SH coefficients, channel-major
};
} // namespace parafluid
