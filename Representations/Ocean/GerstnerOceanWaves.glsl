//=========================================================================
// ParaFluid Gerstner ocean: the wave model on the GPU. Mirrors
// parafluid::ocean::GerstnerOcean::evaluate (Filters/Ocean/Core/GerstnerOcean.cxx) line for line; a
// pvpython test renders both and compares images and depth buffers. Uniforms (oceanAmplitude,
// ...) are declared by VTK from the representation's custom uniforms; OCEAN_FLOOR is defined
// when a bathymetry is bound, OCEAN_DEEP in deep water without one (oceanFloorTex: elevation; oceanPhase0..7: phase, wavenumber and
// cross-wise phase derivative of each wave on its own grid along the wave's direction).
//=========================================================================

// sin and cos of theta0 - delta, delta in [0, 0.5] (the wind's phase shift): as shiftPhase in C++.
void oceanShiftPhase(float s0, float c0, float delta, out float s, out float c)
{
  float d2 = delta * delta;
  float sd = delta * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0)));
  float cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0 * (1.0 - d2 / 56.0)));
  s = s0 * cd - c0 * sd;
  c = c0 * cd + s0 * sd;
}

float oceanSmoothstep(float lo, float hi, float v)
{
  float t = clamp((v - lo) / (hi - lo), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

#ifdef OCEAN_FLOOR
// Data textures hold 24-bit fixed point in their RGB bytes (see makeFixedPointTexture).
float oceanDecode(vec4 texel, float lowest, float span)
{
  vec3 b = floor(texel.rgb * 255.0 + 0.5);
  return lowest + (b.r * 65536.0 + b.g * 256.0 + b.b) * (span / 16777215.0);
}

float oceanElevation(int i, int j)
{
  return oceanDecode(texelFetch(oceanFloorTex, ivec2(i, j), 0), oceanFloorRange.x, oceanFloorRange.y);
}

// Depth below sea level at p and its gradient (bilinear, clamped at the grid's edges).
float oceanFloorDepth(vec2 p, out vec2 slope)
{
  vec2 g = clamp((p - oceanFloorOrigin) / oceanFloorSpacing, vec2(0.0), oceanFloorSize - vec2(1.0));
  int i = min(int(g.x), int(oceanFloorSize.x) - 2);
  int j = min(int(g.y), int(oceanFloorSize.y) - 2);
  vec2 f = g - vec2(float(i), float(j));
  float e00 = oceanElevation(i, j), e10 = oceanElevation(i + 1, j);
  float e01 = oceanElevation(i, j + 1), e11 = oceanElevation(i + 1, j + 1);
  float e = (1.0 - f.x) * (1.0 - f.y) * e00 + f.x * (1.0 - f.y) * e10 + (1.0 - f.x) * f.y * e01 + f.x * f.y * e11;
  slope.x = -((1.0 - f.y) * (e10 - e00) + f.y * (e11 - e01)) / oceanFloorSpacing.x;
  slope.y = -((1.0 - f.x) * (e01 - e00) + f.x * (e11 - e10)) / oceanFloorSpacing.y;
  return oceanSeaLevel - e;
}

vec4 oceanPhaseFetch(int w, ivec2 ij)
{
  // Samplers cannot be indexed by a loop variable in GLSL 1.50.
  if (w == 0) return texelFetch(oceanPhase0, ij, 0);
  if (w == 1) return texelFetch(oceanPhase1, ij, 0);
  if (w == 2) return texelFetch(oceanPhase2, ij, 0);
  if (w == 3) return texelFetch(oceanPhase3, ij, 0);
  if (w == 4) return texelFetch(oceanPhase4, ij, 0);
  if (w == 5) return texelFetch(oceanPhase5, ij, 0);
  if (w == 6) return texelFetch(oceanPhase6, ij, 0);
  return texelFetch(oceanPhase7, ij, 0);
}

// (phase, wavenumber, phase derivative across) of wave w at sample (i, j): three texels.
vec3 oceanPhaseTexel(int w, ivec2 ij)
{
  return vec3(oceanDecode(oceanPhaseFetch(w, ivec2(3 * ij.x, ij.y)), oceanPhaseLo[w], oceanPhaseSpan[w]),
    oceanDecode(oceanPhaseFetch(w, ivec2(3 * ij.x + 1, ij.y)), oceanKLo[w], oceanKSpan[w]),
    oceanDecode(oceanPhaseFetch(w, ivec2(3 * ij.x + 2, ij.y)), oceanAcrossLo[w], oceanAcrossSpan[w]));
}

// Phase, local wavenumber and wave vector of wave w at p (WavePhaseField::sample).
void oceanSamplePhase(int w, vec2 p, out float phase, out float k, out vec2 gradient)
{
  vec2 d = vec2(oceanDirX[w], oceanDirY[w]);
  float s = d.x * p.x + d.y * p.y, t = -d.y * p.x + d.x * p.y;
  float ns = oceanGridNS[w], nt = oceanGridNT[w], step = oceanGridStep[w];
  float gs = (s - oceanGridS0[w]) / step, gt = (t - oceanGridT0[w]) / step;
  float cs = clamp(gs, 0.0, ns - 1.0), ct = clamp(gt, 0.0, nt - 1.0);
  int i = min(int(cs), max(int(ns) - 2, 0)), j = min(int(ct), max(int(nt) - 2, 0));
  float fx = ns > 1.0 ? cs - float(i) : 0.0, fy = nt > 1.0 ? ct - float(j) : 0.0;
  int i1 = min(i + 1, int(ns) - 1), j1 = min(j + 1, int(nt) - 1);
  vec3 v = (1.0 - fx) * (1.0 - fy) * oceanPhaseTexel(w, ivec2(i, j)) + fx * (1.0 - fy) * oceanPhaseTexel(w, ivec2(i1, j)) +
    (1.0 - fx) * fy * oceanPhaseTexel(w, ivec2(i, j1)) + fx * fy * oceanPhaseTexel(w, ivec2(i1, j1));
  k = v.g;
  phase = v.r + k * (gs - cs) * step;
  gradient = vec2(k * d.x - v.b * d.y, k * d.y + v.b * d.x);
}
#endif

// Displacement of the rest point p, its derivatives along x and y, the Jacobian of the horizontal
// map, foam (0..1) and water depth (a large number in deep water).
void oceanEvaluate(vec2 p, out vec3 offset, out vec3 dx, out vec3 dy, out float jacobian, out float foam, out float depth)
{
  offset = vec3(0.0);
  dx = vec3(0.0);
  dy = vec3(0.0);
  float breakingCrest = 0.0;
  vec2 slope = vec2(0.0);
#ifdef OCEAN_FLOOR
  float h = oceanFloorDepth(p, slope);
  bool deep = false;
#else
  float h = oceanDepth;
  bool deep = oceanDepth <= 0.0;
#endif
#ifdef OCEAN_DEEP
  {
    // Deep water in one pass (no shore factors, no breaking, no tilt; the steepness clamp already
    // holds the summed steepness under MaxSteepness): what most frames draw, and the vertex
    // shader's cost in software rendering.
    for (int i = 0; i < oceanWaveCount; ++i)
    {
      float A = oceanAmplitude[i], Q = oceanSteepness[i], k = oceanUniformK[i];
      vec2 d = vec2(oceanDirX[i], oceanDirY[i]);
      vec2 g = k * d;
      float theta0 = g.x * p.x + g.y * p.y + oceanPhaseNow[i];
      float s0 = sin(theta0), c0 = cos(theta0);
      float S, C;
      oceanShiftPhase(s0, c0, 0.5 * oceanLean[i] * (1.0 + s0), S, C);
      float along = Q * A * C, up = A * S;
      float dAlong = -Q * A * S, dUp = A * C;
      offset += vec3(d * along, up);
      vec2 gc = (1.0 - 0.5 * oceanLean[i] * c0) * g;
      dx += vec3(d * dAlong, dUp) * gc.x;
      dy += vec3(d * dAlong, dUp) * gc.y;
    }
  }
#else
  if (h > oceanMinDepth)
  {
    // Pass 1: phases and the shore factors, and the summed horizontal steepness.
    float sinTheta[16], cosTheta[16], cosTheta0[16], kLocal[16], gxs[16], gys[16], dirx[16], diry[16], sx[16], sz[16], decay[16];
    float horizontal = 0.0;
    for (int i = 0; i < oceanWaveCount; ++i)
    {
      float phi, k;
      vec2 g;
#ifdef OCEAN_FLOOR
      oceanSamplePhase(i, p, phi, k, g);
#else
      k = oceanUniformK[i];
      g = k * vec2(oceanDirX[i], oceanDirY[i]);
      phi = g.x * p.x + g.y * p.y;
#endif
      float gl = length(g);
      dirx[i] = gl > 0.0 ? g.x / gl : oceanDirX[i];
      diry[i] = gl > 0.0 ? g.y / gl : oceanDirY[i];
      kLocal[i] = k;
      gxs[i] = g.x;
      gys[i] = g.y;
      // oceanPhaseNow = phase - omega t, reduced modulo 2 pi on the CPU in double precision.
      float theta0 = phi + oceanPhaseNow[i];
      float s0 = sin(theta0);
      cosTheta0[i] = cos(theta0);
      oceanShiftPhase(s0, cosTheta0[i], 0.5 * oceanLean[i] * (1.0 + s0), sinTheta[i], cosTheta[i]);
      decay[i] = deep ? 0.0 : exp(-k * h);
      sx[i] = 1.0 / (1.0 - decay[i]);
      sz[i] = 1.0 - decay[i];
      horizontal += oceanSteepness[i] * oceanAmplitude[i] * sx[i] * gl * (1.0 + 0.5 * oceanLean[i]);
    }
    float limit = horizontal > oceanMaxSteepness ? oceanMaxSteepness / horizontal : 1.0;
    // Pass 2: orbits, breaking, displacement and its derivatives.
    for (int i = 0; i < oceanWaveCount; ++i)
    {
      float A = oceanAmplitude[i], Q = oceanSteepness[i];
      float sxl = sx[i] * limit, szl = sz[i];
      float S = sinTheta[i], C = cosTheta[i];
      float P = max(S, 0.0), dP = S > 0.0 ? C : 0.0;
      float b = deep ? 0.0 : oceanSmoothstep(0.7 * oceanBreakRatio, oceanBreakRatio, 2.0 * A * szl / h);
      breakingCrest = max(breakingCrest, b * P);
      float ahead = -(slope.x * dirx[i] + slope.y * diry[i]);
      float alpha = atan(max(ahead, 0.0)) * decay[i] + b * oceanBreakLean * P;
      float dAlpha = b * oceanBreakLean * dP;
      float u = Q * A * sxl * C + b * oceanBreakShift * A * P * P;
      float du = -Q * A * sxl * S + b * oceanBreakShift * A * 2.0 * P * dP;
      float v = A * szl * S + b * oceanBreakStretch * A * szl * P * P;
      float dv = A * szl * C + b * oceanBreakStretch * A * szl * 2.0 * P * dP;
      float ca = cos(alpha), sa = sin(alpha);
      float along = u * ca + v * sa;
      float up = v * ca - u * sa;
      float dAlong = du * ca + dv * sa + (-u * sa + v * ca) * dAlpha;
      float dUp = dv * ca - du * sa + (-v * sa - u * ca) * dAlpha;
      offset += vec3(dirx[i] * along, diry[i] * along, up);
      float chain = 1.0 - 0.5 * oceanLean[i] * cosTheta0[i];
      float gx = chain * gxs[i], gy = chain * gys[i];
      dx += vec3(dirx[i] * dAlong * gx, diry[i] * dAlong * gx, dUp * gx);
      dy += vec3(dirx[i] * dAlong * gy, diry[i] * dAlong * gy, dUp * gy);
    }
  }
#endif
  jacobian = (1.0 + dx.x) * (1.0 + dy.y) - dx.y * dy.x;
  foam = clamp(max(breakingCrest, (0.6 - jacobian) / 0.6), 0.0, 1.0);
  depth = deep ? 1.0e30 : max(h, 0.0);
}
