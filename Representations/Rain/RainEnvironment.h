#pragma once
// The light around the rain as spherical harmonics (band 4, 16 RGB coefficients), projected on the
// CPU when it changes: six cube-map images set on the representation, or else the view's
// background (a colour or a bottom-to-top gradient along the camera's up).
#include "vtkSmartPointer.h"

#include <array>
#include <string>

class vtkRenderer;
class vtkImageData;

namespace parafluid
{
class RainEnvironment
{
public:
  /// Image file of cube-map face 0..5 (+X, -X, +Y, -Y, +Z, -Z); empty: none.
  void SetImage(int face, const std::string& file);
  /// The coefficients for this frame, channel-major (16 red, 16 green, 16 blue): the images', or
  /// the view's background from `bottom` to `top` about the renderer's camera up.
  const std::array<float, 48>& Coefficients(vtkRenderer* renderer, const double bottom[3], const double top[3]);
  /// The mean radiance (RGB) over the sphere.
  void Average(float rgb[3]) const;

private:
  bool ProjectImages();

  std::string Files[6];
  bool FilesChanged = true;
  bool HaveImages = false;
  std::array<float, 48> Images{};
  std::array<float, 48> Current{};
  std::array<double, 9> BackgroundKey{}; // background colours, gradient flag and up vector last projected
  bool HaveBackground = false;
};
} // namespace parafluid
