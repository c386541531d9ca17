//=========================================================================
// Narrow-range filter (Truong & Yuksel 2018), one separable 1D pass along stepDir. Around the
// centre depth d0 only a band of half-width mu counts: samples more than mu in front are
// ignored (a nearer sheet must not pull this surface forward), samples more than mu behind, and
// empty pixels, are clamped to d0 + mu (so silhouettes round off instead of bleeding into the
// background). The Gaussian's width follows the particle's projected size: filterSize particle
// radii at any zoom, with at most maxRadius taps each side (spread out when the width needs more).
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
    // Gaps between splats narrower than the filter fill in (they are not the fluid's edge).
    d0 = gapDepth(p, stepDir, maxRadius, rangeFactor * particleRadius);
    if (d0 <= 0.0)
    {
      gl_FragData[0] = vec4(0.0);
      return;
    }
  }
  float sigma;
  int stride;
  int n = filterTaps(d0, particleRadius, filterSize, maxRadius, strideShift, sigma, stride);
  float mu = rangeFactor * particleRadius;
  float inv2s2 = 0.5 / max(sigma * sigma, 1e-6);
  float sum = 0.0;
  float weights = 0.0;
  for (int i = -n; i <= n; ++i)
  {
    float d = fetchDepth(p + i * stride * stepDir);
    if (d <= 0.0 || d > d0 + mu)
    {
      d = d0 + mu;
    }
    else if (d < d0 - mu)
    {
      continue;
    }
    float w = exp(-float(i * i * stride * stride) * inv2s2);
    sum += w * d;
    weights += w;
  }
  gl_FragData[0] = vec4(sum / weights, 0.0, 0.0, 0.0);
}
