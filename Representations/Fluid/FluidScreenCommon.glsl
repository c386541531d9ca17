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

// Half-width in pixels (and Gaussian sigma) of the narrow-range and bilateral filters at depth
// d0: filterSize particle radii across on screen, at most maxRadius pixels each side.
int filterHalfWidth(float d0, float particleRadius, float filterSize, int maxRadius, out float sigma)
{
  sigma = 0.5 * filterSize * particleRadius / pixelFootprint(d0).x;
  int n = clamp(int(ceil(2.0 * sigma)), 1, maxRadius);
  sigma = min(sigma, 0.5 * float(n));
  return n;
}
