#pragma once
// The screen-space fluid's full-screen passes: a fragment program over the fluid's rectangle
// (vtkOpenGLQuadHelper), built once per context from the shared GLSL prelude and its body; and
// the declarations every pass header needs.
#include "FluidFrame.h"

#include <memory>

class vtkOpenGLQuadHelper;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
class FluidScreenTargets;

/// Builds `quad` from FluidScreenCommon.glsl, `defines` and `body` the first time, readies its
/// program after that, and sets the uniforms every screen pass reads (rectangle, viewport size,
/// projection). Returns the program, or null when it did not compile.
vtkShaderProgram* readyScreenQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad, const FluidFrame& frame, const char* body,
                                  const char* defines = "");

/// One pass of `quad` from `source` (bound as the sampler `sourceName`) into `target`, through the
/// frame's framebuffer; counts it.
void runScreenQuad(FluidFrame& frame, vtkOpenGLQuadHelper* quad, vtkTextureObject* source, vtkTextureObject* target,
                   const char* sourceName);

void releaseScreenQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkWindow* window);
} // namespace parafluid
