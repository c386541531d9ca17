//=========================================================================
// Separable Gaussian blur of the additive thickness splats (world length of fluid along each
// pixel's ray) at reduced resolution, one 1D pass along stepDir with half-width radius pixels.
//=========================================================================
uniform sampler2D thicknessTex;
uniform ivec2 stepDir;
uniform int radius;

//VTK::Output::Dec

void main()
{
  ivec2 p = targetPixel();
  float sigma = 0.5 * float(radius);
  float inv2s2 = 0.5 / (sigma * sigma);
  float sum = 0.0;
  float weights = 0.0;
  for (int i = -radius; i <= radius; ++i)
  {
    ivec2 q = p + i * stepDir;
    float w = exp(-float(i * i) * inv2s2);
    weights += w;
    if (all(greaterThanEqual(q, rectMin)) && all(lessThan(q, rectMax)))
    {
      sum += w * texelFetch(thicknessTex, q, 0).r;
    }
  }
  gl_FragData[0] = vec4(sum / weights, 0.0, 0.0, 0.0);
}
