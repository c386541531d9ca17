//VTK::System::Dec
//=========================================================================
// ParaFluid ray-marched fluid, start/stop depth from splats: per coarse pixel, blended by GL_MIN,
//   (splash nearest, -splash farthest, bulk nearest, -bulk farthest) view depth,
// cleared to a huge value (no sphere). See RayMarchBoundsVS.glsl.
//=========================================================================
flat in vec2 depthSpan;
flat in float splash;

//VTK::Output::Dec

void main()
{
  const float none = 1.0e30;
  gl_FragData[0] = splash > 0.5 ? vec4(depthSpan.x, -depthSpan.y, none, none)
                                : vec4(none, none, depthSpan.x, -depthSpan.y);
}
