#pragma once
// Where the screen-space fluid lands on screen, from its bounds and the camera: pure CPU math (no
// VTK, no OpenGL), so it is unit-tested on its own (Testing/Fluid/FluidFootprintTest.cxx).

namespace parafluid
{
struct FluidFootprintQuery
{
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 }; // of the particle centres [world units]
  double MaxRadius = 0.0;                  // largest particle radius [world units]
  /// VTK's key matrices model -> view and view -> clip, element (r, c) at [4 r + c]. VTK stores
  /// them transposed for OpenGL: a point x maps to sum_r x_r M(r, c) + M(3, c).
  double ModelView[16] = {};
  double Projection[16] = {};
  bool Parallel = false;
  double NearDistance = 0.0; // the camera's near clipping distance
  int Size[2] = { 0, 0 };    // viewport [pixels]
  int Margin = 0;            // pixels added around the projected bounds (the filters' reach)
  double MaxPointSize = 1.0; // the largest point sprite the context draws [pixels]
};

struct FluidFootprint
{
  /// False when the fluid is all behind the camera or off screen: nothing to draw.
  bool Visible = false;
  /// x0, y0, x1, y1 [viewport pixels], the grown bounds' projection plus the margin, clipped to
  /// the viewport; the whole viewport when part of the bounds is behind the eye.
  int Rect[4] = { 0, 0, 0, 0 };
  double Nearest = 0.0, Farthest = 0.0; // eye distances of the grown bounds' corners
  /// Whether one point sprite per particle is safe: every sphere's centre projects inside the
  /// viewport (a point whose centre is clipped is dropped whole) and no sphere's screen box, at
  /// the nearest depth and the widest angle, exceeds the largest point size.
  bool PointSprites = false;
};

FluidFootprint computeFluidFootprint(const FluidFootprintQuery& query);
} // namespace parafluid
