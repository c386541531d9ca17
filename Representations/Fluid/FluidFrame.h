#pragma once
// What the passes of one screen-space fluid frame share: the window and its state, the passes'
// framebuffer, the viewport, the fluid's rectangle on it, the camera, and the count of GPU passes
// run (which tests read to check that passes a setting does not need are skipped).
class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderer;

namespace parafluid
{
struct FluidFrame
{
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkOpenGLState* State = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr; // the offscreen passes draw through it
  int Size[2] = { 0, 0 };                            // viewport [pixels]
  int Origin[2] = { 0, 0 };                          // its first pixel in the window's framebuffer
  int RectMin[2] = { 0, 0 }, RectMax[2] = { 0, 0 };  // the fluid's rectangle [viewport pixels]
  vtkMatrix4x4* ModelView = nullptr;                 // VTK key matrices (transposed, as uploaded)
  vtkMatrix4x4* Projection = nullptr;
  float ProjectionCoefficients[4] = { 0, 0, 0, 0 }; // x, y scale and offset of the projection
  bool Parallel = false;
  double NearDistance = 0.0;            // near clipping distance
  double Nearest = 0.0, Farthest = 0.0; // the fluid's eye distances
  double MaxRadius = 0.0;               // largest particle radius [world units]
  bool PointSprites = false;            // splats as point sprites (else quads)
  int PassCount = 0;

  int RectWidth() const { return this->RectMax[0] - this->RectMin[0]; }
  int RectHeight() const { return this->RectMax[1] - this->RectMin[1]; }
};
} // namespace parafluid
