#pragma once
// What the fluid passes that shade a surface (screen-space and ray-marched) set alike: the view's
// lights in eye space, the environment to reflect and its orientation, and the background
// colours; the GLSL side is FluidLightingFS.glsl.
class vtkRenderer;
class vtkShaderProgram;
class vtkTexture;

namespace parafluid
{
/// The environment a fluid reflects: `mine` (the representation's cube map) when set, else the
/// renderer's environment texture; null when neither is a cube map (then the background colours).
vtkTexture* chooseFluidEnvironment(vtkRenderer* renderer, vtkTexture* mine);

/// Sets lightCount, lightDirectionVC, lightColor (up to 6 lights), eyeToCube, backgroundBottom,
/// backgroundTop, and binds `environment` (from chooseFluidEnvironment) as the sampler
/// `environment`; the caller calls environment->PostRender(renderer) after drawing.
void setFluidLighting(vtkShaderProgram* program, vtkRenderer* renderer, vtkTexture* environment);
} // namespace parafluid
