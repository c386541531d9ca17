#pragma once
// The Rain representation's one pass: every drop a streak billboard (one triangle from
// gl_VertexID) coloured by precomputed radiance transfer, blended over the scene with the depth
// test on and depth writes off. Owns the drop's transfer table (computed once per refractive
// index from parafluid::rain::DropTransfer) and, as a texture, its product with the
// environment's coefficients: the drop's radiance toward each view direction.
#include "vtkSmartPointer.h"

#include <array>
#include <vector>

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
    double MaxStreakArea = 1e30; // [pixels] (parafluid::rain::streakAreaLimit)
    bool RadianceOnly = false;
  };
  /// Draws the drops; false when the shader did not compile.
  bool Run(const RainFrame& frame, const RainPointBuffer& drops, const Settings& settings);
  void Release(vtkWindow* window);
  /// The drop's radiance toward each view direction for this frame's environment, RGBA floats,
  /// kRadianceColumns azimuths by kTransferRows heights (what the GPU pass reads as a texture;
  /// the CPU pass, RainStreakCpuPass, reads it here).
  const std::vector<float>& Radiance(const RainFrame& frame, double refractiveIndex);

  /// Rows of the transfer table (view directions: 2 x rows azimuths by rows heights).
  static constexpr int kTransferRows = 64;
  static constexpr int kRadianceColumns = 2 * kTransferRows;

private:
  /// The drop's radiance toward each view direction for this frame's environment (a texture,
  /// rebuilt when the environment or the refractive index changes).
  void EnsureRadiance(const RainFrame& frame, double refractiveIndex);

  vtkShaderProgram* Program = nullptr; // owned by the window's shader cache
  std::vector<float> TransferTable;    // per view direction, the drop's 16 transfer coefficients
  double TransferIndex = 0.0;          // the refractive index it is for
  std::vector<float> RadianceTexels;   // the drop's radiance toward each view direction, RGBA
  vtkSmartPointer<vtkTextureObject> RadianceTexture;
  std::array<float, 48> RadianceEnvironment{}; // the environment it is for
  unsigned int EmptyVAO = 0;
};
} // namespace parafluid
