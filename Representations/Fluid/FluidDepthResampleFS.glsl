//=========================================================================
// The narrow-range filter at reduced resolution (FluidReducedSmoothing): when particles are so
// large on screen that the filter's width needs more taps than it may take, the depth is
// filtered on a target `factor` times smaller each way with dense taps, then brought back.
// DOWNSAMPLE: one pixel of the small target from up to 4 x 4 samples of its factor x factor block
// of the splatted depth: the mean of those within `band` of the nearest (a surface behind
// another in the block does not blend into it); 0 where the block holds no fluid.
// Else (upsampling into full resolution): where the splatted depth holds fluid, the small
// target's smoothed depth by cubic B-spline weights over its 4 x 4 nearest pixels (C2, so the
// normals taken from differences of the result show no seams at the small pixels' edges), using
// only the pixels of one surface (near the one nearest the splatted depth); where the small
// target has none, the splatted depth as it was.
// Empty pixels stay empty but in the holes between splats (where four spheres meet), which take
// the small target's depth (the silhouette is the shading pass's work).
//=========================================================================
uniform sampler2D sourceTex; // DOWNSAMPLE: the splatted depth; else the small target's smoothed depth
uniform int factor;
uniform float band;          // [world units]
uniform ivec2 otherRectMin;  // the rectangle in the other target's pixels (the one read)
uniform ivec2 otherRectMax;

//VTK::Output::Dec

float fetchOther(ivec2 q)
{
  if (any(lessThan(q, otherRectMin)) || any(greaterThanEqual(q, otherRectMax)))
  {
    return 0.0;
  }
  return texelFetch(sourceTex, q, 0).r;
}

#ifdef DOWNSAMPLE
void main()
{
  ivec2 base = targetPixel() * factor;
  int step = max(1, factor / 4);
  float nearest = 1e30;
  for (int j = 0; j < factor; j += step)
  {
    for (int i = 0; i < factor; i += step)
    {
      float d = fetchOther(base + ivec2(i, j));
      if (d > 0.0)
      {
        nearest = min(nearest, d);
      }
    }
  }
  if (nearest > 1e29)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  float sum = 0.0, count = 0.0;
  for (int j = 0; j < factor; j += step)
  {
    for (int i = 0; i < factor; i += step)
    {
      float d = fetchOther(base + ivec2(i, j));
      if (d > 0.0 && d < nearest + band)
      {
        sum += d;
        count += 1.0;
      }
    }
  }
  gl_FragData[0] = vec4(sum / count, 0.0, 0.0, 0.0);
}
#else
vec4 bspline(float t)
{
  float t2 = t * t, t3 = t2 * t;
  return vec4((1.0 - t) * (1.0 - t) * (1.0 - t), 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) /
    6.0;
}

// Whether the empty pixel p lies in a hole between splats (where four spheres meet): splatted
// fluid on both sides along x or along y, within half a particle radius (`radiusPx`).
bool inHole(ivec2 p, float radiusPx)
{
  int r = max(1, int(0.5 * radiusPx));
  bool x = false, y = false;
  for (int i = 1; i <= r; i = i < 4 ? i + 1 : i + i / 4)
  {
    x = x || (fetchDepth(p + ivec2(i, 0)) > 0.0 && fetchDepth(p - ivec2(i, 0)) > 0.0);
    y = y || (fetchDepth(p + ivec2(0, i)) > 0.0 && fetchDepth(p - ivec2(0, i)) > 0.0);
  }
  return x || y;
}

uniform float particleRadius; // [world units]

void main()
{
  ivec2 p = targetPixel();
  float d = fetchDepth(p);
  if (d <= 0.0)
  {
    // A hole between splats takes the smoothed depth of the small pixel over it; the fluid's
    // edge stays where it is.
    float dl = fetchOther(ivec2(floor((vec2(p) + 0.5) / float(factor))));
    if (dl <= 0.0 || !inHole(p, particleRadius / pixelFootprint(dl).x))
    {
      gl_FragData[0] = vec4(0.0);
      return;
    }
    d = dl;
  }
  vec2 u = (vec2(p) + 0.5) / float(factor) - 0.5;
  vec2 cell = floor(u);
  vec4 wx = bspline(u.x - cell.x), wy = bspline(u.y - cell.y);
  // The surface this pixel belongs to: the small pixel nearest the splatted depth in depth (the
  // splatted depth itself can lie a radius or more off the smoothed surface, more at grazing
  // angles), then the small pixels within `band` of that one.
  float layer = 0.0;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      float dl = fetchOther(ivec2(cell) + ivec2(i - 1, j - 1));
      if (dl > 0.0 && (layer <= 0.0 || abs(dl - d) < abs(layer - d)))
      {
        layer = dl;
      }
    }
  }
  // One surface may slope away across the 4 x 4 small pixels: the band grows by three small
  // pixels' width of depth (slopes to 70 degrees from facing the eye keep all their pixels).
  float reach = band + 3.0 * float(factor) * pixelFootprint(layer).x;
  float sum = 0.0, weights = 0.0;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      float dl = fetchOther(ivec2(cell) + ivec2(i - 1, j - 1));
      if (dl > 0.0 && abs(dl - layer) < reach)
      {
        float w = wx[i] * wy[j];
        sum += w * dl;
        weights += w;
      }
    }
  }
  gl_FragData[0] = vec4(weights > 0.0 ? sum / weights : d, 0.0, 0.0, 0.0);
}
#endif
