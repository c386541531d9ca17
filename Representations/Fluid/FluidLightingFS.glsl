//=========================================================================
// ParaFluid fluid surfaces: the light a surface pass reflects (set by setFluidLighting in
// FluidLighting.cxx). The environment is a cube map when FLUID_CUBEMAP is defined, else the view's
// background gradient looked up by the direction's height.
//=========================================================================
uniform int lightCount;
uniform vec3 lightDirectionVC[6]; // direction the light travels, eye space
uniform vec3 lightColor[6];
#ifdef FLUID_CUBEMAP
uniform samplerCube environment;
#endif
uniform mat3 eyeToCube;
uniform vec3 backgroundBottom;
uniform vec3 backgroundTop;

vec3 environmentColor(vec3 dirVC)
{
#ifdef FLUID_CUBEMAP
  return texture(environment, eyeToCube * dirVC).rgb;
#endif
  return mix(backgroundBottom, backgroundTop, clamp(0.5 + 0.5 * dirVC.y, 0.0, 1.0));
}

// Schlick's approximation of the Fresnel reflectance at incidence cosine `cosine`.
float schlickFresnel(float cosine, float refractiveIndex)
{
  float r0 = (refractiveIndex - 1.0) / (refractiveIndex + 1.0);
  r0 *= r0;
  return r0 + (1.0 - r0) * pow(1.0 - clamp(cosine, 0.0, 1.0), 5.0);
}
