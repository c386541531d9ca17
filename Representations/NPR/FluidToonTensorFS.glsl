//=========================================================================
// ParaFluid toon fluid, 1/3: structure tensor of the line image. The line image is the fluid's
// depth in units of lineDepthScale (1 / (particle radius x line depth range)), with the
// background (backgroundValue) well behind the farthest fluid, so silhouettes are edges too.
// Output: (gx^2, gx gy, gy^2) of its central differences.
//=========================================================================
uniform float lineDepthScale;
uniform float backgroundValue;

//VTK::Output::Dec

float lineImage(ivec2 q)
{
  float d = fetchDepth(q);
  return d > 0.0 ? d * lineDepthScale : backgroundValue;
}

void main()
{
  ivec2 p = targetPixel();
  // Sobel: its smoothing across the derivative keeps single-pixel noise out of the orientation.
  float a = lineImage(p + ivec2(-1, -1)), b = lineImage(p + ivec2(0, -1)), c = lineImage(p + ivec2(1, -1));
  float d = lineImage(p + ivec2(-1, 0)), f = lineImage(p + ivec2(1, 0));
  float g = lineImage(p + ivec2(-1, 1)), h = lineImage(p + ivec2(0, 1)), i = lineImage(p + ivec2(1, 1));
  float gx = 0.25 * ((c + 2.0 * f + i) - (a + 2.0 * d + g));
  float gy = 0.25 * ((g + 2.0 * h + i) - (a + 2.0 * b + c));
  gl_FragData[0] = vec4(gx * gx, gx * gy, gy * gy, 0.0);
}
