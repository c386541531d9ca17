//=========================================================================
// Screen-space curvature flow (van der Laan, Green & Sainz 2009), one explicit step: the depth
// moves by the mean curvature H of the depth surface, d <- d + dt H, which flattens bumps and
// keeps the large shape. Derivatives are taken over the pixel's world footprint at d (this drops
// the paper's second-order perspective coupling term). Neighbours that are empty or further
// than rangeFactor particle radii in depth are boundaries: one-sided first derivatives, no
// second derivative across them. The step dt = stepFactor / (1/hx^2 + 1/hy^2) over the footprints
// hx, hy is stable for stepFactor < 1 (the 5-point stencil's limit for d_t = laplacian(d) / 2).
//=========================================================================
uniform float particleRadius;
uniform float rangeFactor;
uniform float stepFactor;

//VTK::Output::Dec

float derivative(float minus, float centre, float plus, bool hasMinus, bool hasPlus)
{
  if (hasMinus && hasPlus)
  {
    return 0.5 * (plus - minus);
  }
  if (hasPlus)
  {
    return plus - centre;
  }
  if (hasMinus)
  {
    return centre - minus;
  }
  return 0.0;
}

void main()
{
  ivec2 p = targetPixel();
  float d0 = fetchDepth(p);
  if (d0 <= 0.0)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  float mu = rangeFactor * particleRadius;
  float l = fetchDepth(p - ivec2(1, 0));
  float r = fetchDepth(p + ivec2(1, 0));
  float b = fetchDepth(p - ivec2(0, 1));
  float t = fetchDepth(p + ivec2(0, 1));
  bool hl = l > 0.0 && abs(l - d0) < mu;
  bool hr = r > 0.0 && abs(r - d0) < mu;
  bool hb = b > 0.0 && abs(b - d0) < mu;
  bool ht = t > 0.0 && abs(t - d0) < mu;
  vec2 h = pixelFootprint(d0);
  float zx = derivative(l, d0, r, hl, hr) / h.x;
  float zy = derivative(b, d0, t, hb, ht) / h.y;
  float zxx = (hl && hr) ? (l - 2.0 * d0 + r) / (h.x * h.x) : 0.0;
  float zyy = (hb && ht) ? (b - 2.0 * d0 + t) / (h.y * h.y) : 0.0;
  float zxy = 0.0;
  if (hl && hr && hb && ht)
  {
    float pp = fetchDepth(p + ivec2(1, 1));
    float pm = fetchDepth(p + ivec2(1, -1));
    float mp = fetchDepth(p + ivec2(-1, 1));
    float mm = fetchDepth(p + ivec2(-1, -1));
    if (pp > 0.0 && pm > 0.0 && mp > 0.0 && mm > 0.0)
    {
      zxy = 0.25 * (pp - pm - mp + mm) / (h.x * h.y);
    }
  }
  float g = 1.0 + zx * zx + zy * zy;
  float twoH = ((1.0 + zy * zy) * zxx - 2.0 * zx * zy * zxy + (1.0 + zx * zx) * zyy) / (g * sqrt(g));
  float dt = stepFactor / (1.0 / (h.x * h.x) + 1.0 / (h.y * h.y));
  // Never move more than a particle radius in one step (steep silhouette pixels).
  float move = clamp(dt * 0.5 * twoH, -particleRadius, particleRadius);
  gl_FragData[0] = vec4(d0 + move, 0.0, 0.0, 0.0);
}
