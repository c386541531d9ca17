#pragma once
// Pass 1 of the screen-space fluid: every particle an exact ray-traced sphere, writing the eye
// distance of the nearest surface (and the particle colour when colouring by an array) into the
// depth target; for transparent fluid also the additive chord lengths into the thickness target at
// reduced resolution. One point sprite per particle when the frame allows it, else six-vertex quads.
#include "vtkType.h"

class vtkShaderProgram;
class vtkWindow;

namespace parafluid
{
class FluidParticleBuffers;
class FluidScreenTargets;
struct FluidFrame;

class FluidSplatPass
{
public:
  /// Builds (or readies) the programs the frame needs; false when one does not compile. The
  /// thickness program is built first so that a failure stops before any drawing.
  bool Prepare(const FluidFrame& frame, const FluidParticleBuffers& particles, const FluidScreenTargets& targets,
               bool thickness);
  /// Draws the depth splats and, with `thickness`, the thickness splats. Leaves the depth test
  /// and depth writes off.
  void Run(FluidFrame& frame, const FluidParticleBuffers& particles, FluidScreenTargets& targets, bool thickness);
  /// The frame's thickness factor it used (0 when no thickness was drawn).
  int LastThicknessFactor() const { return this->ThicknessFactor; }

  void Release(vtkWindow* window);

private:
  vtkShaderProgram* Ready(const FluidFrame& frame, const FluidParticleBuffers& particles,
                          const FluidScreenTargets& targets, int which);
  void Draw(const FluidFrame& frame, vtkIdType count) const;

  // Depth (0) or thickness (1), + 2 for point sprites; built apart so that no pass carries
  // another's branches and varyings (on llvmpipe the thickness pass's branches cost the depth pass
  // a third of its speed). Owned by the window's shader cache.
  vtkShaderProgram* Programs[4] = { nullptr, nullptr, nullptr, nullptr };
  int ThicknessFactor = 0;
};
} // namespace parafluid
