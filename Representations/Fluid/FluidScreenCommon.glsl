//=========================================================================
// ParaFluid screen-space fluid: what every full-screen pass shares. Depth targets hold the
// eye-space distance d = -z_eye of the fluid's front surface, 0 where there is no fluid. Passes
// only run inside that rectangle (the fluid's bounds on screen, with a margin): pixels outside it are
// never written, so reads outside it count as "no fluid".
//=========================================================================
uniform sampler2D depthTex;
uniform ivec2 rectMin;        // the fluid's rectangle in target pixels: first pixel
uniform ivec2 rectMax;        // and one past the last
uniform vec2 viewportSize;    // pixels
uniform int parallelProjection;
uniform vec4 projection;      // math-convention P00, P11, and P02, P12 (perspective) or P03, P13

in vec2 texCoord; // 0..1 across the target

// The target pixel this fragment writes.
ivec2 targetPixel()
{
  return ivec2(texCoord * viewportSize);
}

float fetchDepth(ivec2 q)
{
  if (any(lessThan(q, rectMin)) || any(greaterThanEqual(q, rectMax)))
  {
    return 0.0;
  }
  return texelFetch(depthTex, q, 0).r;
}

// Eye-space position of the surface seen through pixel centre `pixel` at distance d.
vec3 eyePosition(vec2 pixel, float d)
{
  vec2 ndc = pixel / viewportSize * 2.0 - 1.0;
  if (parallelProjection != 0)
  {
    return vec3((ndc - projection.zw) / projection.xy, -d);
  }
  return vec3(d * (ndc + projection.zw) / projection.xy, -d);
}

// World length of one pixel (horizontal, vertical) at distance d.
vec2 pixelFootprint(float d)
{
  vec2 perUnit = 2.0 / (viewportSize * projection.xy);
  return parallelProjection != 0 ? perUnit : perUnit * d;
}

// Taps each side, their spacing in pixels (stride) and the Gaussian's sigma [pixels] of the
// narrow-range and bilateral filters at depth d0: sigma is half of filterSize particle radii on
// screen at any zoom. At most maxRadius taps each side bound the cost per pixel: when the reach
// (2 sigma) needs more, the taps spread out (stride > 1) instead of the reach being cut, so close
// up a particle is still smoothed over its whole width. Earlier iterations use strides halved
// `strideShift` times (a trous, Dammertz et al. 2010): they take out the splats' creases first, so
// the sparse taps of the last iterations do not alias the particle lattice.
// With spreadTaps 0 the reach is cut at maxRadius pixels instead (the styles' look).
uniform int spreadTaps;
int filterTaps(float d0, float particleRadius, float filterSize, int maxRadius, int strideShift, out float sigma,
               out int stride)
{
  sigma = 0.5 * filterSize * particleRadius / pixelFootprint(d0).x;
  int reach = int(ceil(2.0 * sigma));
  if (spreadTaps == 0)
  {
    stride = 1;
    int n = clamp(reach, 1, maxRadius);
    sigma = min(sigma, 0.5 * float(n));
    return n;
  }
  stride = max(1, ((reach + maxRadius - 1) / maxRadius) >> strideShift);
  return clamp((reach + stride - 1) / stride, 1, maxRadius);
}

// Depth for an empty pixel that lies in a gap between splats along `dir`: where fluid lies within
// `reach` pixels on both sides at depths within `band` of each other, the depth interpolated
// between the nearest fluid pixels on each side (a gap between touching spheres, e.g. where four
// meet on a lattice seen along its axis); else 0 (the fluid's edge, or the gap between a drop
// and the fluid behind it, stays an edge).
float gapDepth(ivec2 p, ivec2 dir, int reach, float band)
{
  float before = 0.0, after = 0.0;
  int at = 0, bt = 0;
  for (int i = 1; i <= reach && (before <= 0.0 || after <= 0.0); ++i)
  {
    if (before <= 0.0)
    {
      before = fetchDepth(p - i * dir);
      at = i;
    }
    if (after <= 0.0)
    {
      after = fetchDepth(p + i * dir);
      bt = i;
    }
  }
  if (before <= 0.0 || after <= 0.0 || abs(before - after) > band)
  {
    return 0.0;
  }
  return mix(before, after, float(at) / float(at + bt));
}
