//=========================================================================
// Separable Gaussian blur, one 1D pass along stepDir with half-width radius pixels, of all four
// channels: the thickness splats (world length of fluid along each pixel's ray, at reduced
// resolution) and the toon structure tensor.
//=========================================================================
uniform sampler2D sourceTex;
uniform ivec2 stepDir;
uniform int radius;

//VTK::Output::Dec

void main()
{
  ivec2 p = targetPixel();
  float sigma = 0.5 * float(radius);
  float inv2s2 = 0.5 / (sigma * sigma);
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int i = -radius; i <= radius; ++i)
  {
    ivec2 q = p + i * stepDir;
    float w = exp(-float(i * i) * inv2s2);
    weights += w;
    if (all(greaterThanEqual(q, rectMin)) && all(lessThan(q, rectMax)))
    {
      sum += w * texelFetch(sourceTex, q, 0);
    }
  }
  gl_FragData[0] = sum / weights;
}
