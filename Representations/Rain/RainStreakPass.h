#pragma once
// The Rain representation's one pass: every drop a streak billboard (six vertices from
// gl_VertexID) coloured by precomputed radiance transfer, blended over the scene with the depth
// test on and depth writes off. Owns the drop's transfer table (a texture computed once per
// refractive index from parafluid::rain::DropTransfer).
#include "vtkSmartPointer.h"

class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
class RainPointBuffer;
struct RainFrame;

class RainStreakPass
{
public:
  struct Settings
  {
    double RefractiveIndex = 1.333;
    double Brightness = 1.0;
    double Opacity = 0.6;
    double FogDistance = 0.0; // [m]; 0: none
    double WidthScale = 1.0;
    bool RadianceOnly = false;
  };
  /// Draws the drops; false when the shader did not compile.
  bool Run(const RainFrame& frame, const RainPointBuffer& drops, const Settings& settings);
  void Release(vtkWindow* window);

  /// Rows of the transfer table (view directions: 2 x rows azimuths by rows heights).
  static constexpr int kTransferRows = 64;

private:
  void EnsureTransfer(const RainFrame& frame, double refractiveIndex);

  vtkShaderProgram* Program = nullptr; // owned by the window's shader cache
  vtkSmartPointer<vtkTextureObject> Transfer;
  double TransferIndex = 0.0;
  unsigned int EmptyVAO = 0;
};
} // namespace parafluid
