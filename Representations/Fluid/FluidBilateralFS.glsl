//=========================================================================
// Separable bilateral filter, one 1D pass along stepDir: a Gaussian in pixels (width from the
// particle's projected size at any zoom, as the narrow-range filter) times a Gaussian in depth of width
// rangeFactor particle radii, so samples across a depth jump weigh nothing. Empty pixels are
// left out.
//=========================================================================
uniform ivec2 stepDir;
uniform float particleRadius;
uniform float filterSize;
uniform int maxRadius;
uniform int strideShift; // the a trous level: strides halved this many times
uniform float rangeFactor;

//VTK::Output::Dec

void main()
{
  ivec2 p = targetPixel();
  float d0 = fetchDepth(p);
  if (d0 <= 0.0)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  float sigma;
  int stride;
  int n = filterTaps(d0, particleRadius, filterSize, maxRadius, strideShift, sigma, stride);
  float inv2s2 = 0.5 / max(sigma * sigma, 1e-6);
  float sd = rangeFactor * particleRadius;
  float inv2sd2 = 0.5 / (sd * sd);
  float sum = 0.0;
  float weights = 0.0;
  for (int i = -n; i <= n; ++i)
  {
    float d = fetchDepth(p + i * stride * stepDir);
    if (d <= 0.0)
    {
      continue;
    }
    float w = exp(-float(i * i * stride * stride) * inv2s2 - (d - d0) * (d - d0) * inv2sd2);
    sum += w * d;
    weights += w;
  }
  gl_FragData[0] = vec4(sum / weights, 0.0, 0.0, 0.0);
}
