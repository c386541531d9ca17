//=========================================================================
// ParaFluid ray-marched fluid: one ray per pixel through the particles' covered-volume fraction
//   phi(x) = V sum_j W(|x - x_j|),  W = poly6 of support kernelRadius,  V = d^3
// (Particle Surface's field), evaluated exactly by summing the particles of the grid cells the
// kernel reaches (cells are at least kernelRadius wide: at most 3 per axis). The surface is where
// phi crosses isoValue.
// Empty-space skipping (Wu et al. 2022): a block or cell whose conservative bound of phi is below
// the iso value (DensityCellGrid) is crossed in one stride, so small steps are taken only near
// the fluid; a ray through spray samples only the cells around the spray, then strides on.
// Start/stop depth from splats (SPLAT_BOUNDS; after Xiao et al. 2017, RayMarchBoundsPass): the
// surface lies within the kernel-radius spheres of the particles near it, so a ray samples only
// between their nearest and farthest depth over its pixel; splash and bulk have a pair each, and a
// ray through spray marches the spray's span, then jumps to the bulk's.
// Hit refinement: bisection of the last step, then a secant step, so the surface does not band.
// Inside the fluid the march strides 8 steps at a time (it only needs the exit).
// Normals: phi's analytic gradient. Shading: Schlick's Fresnel reflection of the environment;
// for transparent fluid the ray bends by Snell's law at the entry, marches inside the fluid to
// the exit (the true path length L), bends again, and takes the opaque scene behind it there,
// attenuated by Beer-Lambert exp(-sigma L), sigma = -ln(fluidColor) / attenuationDistance.
// Marching happens in the actor's model coordinates; depth is written, so the fluid and the
// opaque scene hide each other.
//=========================================================================
uniform samplerBuffer particles;     // sorted x, y, z, 0 [model units]
uniform usamplerBuffer cellStart;    // first sorted slot of each cell; bit 31: phi may reach the iso value
uniform usamplerBuffer blockOccupied;
#ifdef PARTICLE_COLORS
uniform samplerBuffer particleColors; // per sorted slot
uniform float colorMix;
#endif
uniform sampler2D opaqueDepthTex;    // window depth of the opaque scene (full resolution)
#ifdef SPLAT_BOUNDS
uniform sampler2D boundsTex; // per BOUNDS_PIXELS march pixels: splash near, -far, bulk near, -far [view depth]
#endif
#ifdef TRANSPARENT_FLUID
uniform sampler2D opaqueColor;
#endif
uniform vec3 gridOrigin;
uniform float cellSize;
uniform int gridDimsV[3]; // cells per axis
uniform int blockDimsV[3];
#define gridDims ivec3(gridDimsV[0], gridDimsV[1], gridDimsV[2])
#define blockDims ivec3(blockDimsV[0], blockDimsV[1], blockDimsV[2])
uniform int blockCells;
uniform float kernelRadius;
uniform float kernelScale; // phi = kernelScale * sum (1 - s^2 / r^2)^3
uniform float isoValue;
uniform float stepLength;  // [model units]
uniform int maxSteps;      // samples of phi per ray (refinement included)
uniform int skipping;
uniform mat4 eyeToModel;
uniform mat4 modelToEye;
uniform mat4 VCDCMatrix;
uniform vec2 depthCoefficients; // P22, P23 of the projection (math convention)
uniform ivec2 marchSize;        // pixels of the target this pass writes
uniform float pixelScale;       // viewport pixels per target pixel (1 / ResolutionScale)
uniform int displayMode;        // 0 opaque, 1 transparent, 2 normals, 3 steps
uniform vec3 fluidColor;
uniform float attenuationDistance;
uniform float refractiveIndex;
uniform float shininess;
uniform float specularStrength;
uniform float ambient;

//VTK::Output::Dec

int samples = 0;

// phi at x [model units].
float phiAt(vec3 x)
{
  ++samples;
  vec3 g = (x - gridOrigin) / cellSize;
  float rho = kernelRadius / cellSize;
  ivec3 lo = max(ivec3(floor(g - rho)), ivec3(0));
  ivec3 hi = min(ivec3(floor(g + rho)), gridDims - 1);
  if (any(greaterThan(lo, hi)))
  {
    return 0.0; // beyond the grid (rows past its end must not be read)
  }
  float inv2 = 1.0 / (kernelRadius * kernelRadius);
  float sum = 0.0;
  for (int z = lo.z; z <= hi.z; ++z)
  {
    for (int y = lo.y; y <= hi.y; ++y)
    {
      int row = (z * gridDims.y + y) * gridDims.x;
      int begin = int(texelFetch(cellStart, row + lo.x).r & 0x7fffffffu);
      int end = int(texelFetch(cellStart, row + hi.x + 1).r & 0x7fffffffu);
      for (int k = begin; k < end; ++k)
      {
        vec3 e = texelFetch(particles, k).xyz - x;
        float q = max(1.0 - dot(e, e) * inv2, 0.0);
        sum += q * q * q;
      }
    }
  }
  return sum * kernelScale;
}

// The outward normal (minus phi's gradient, normalised) at x [model], and the kernel-weighted
// colour of the particles there.
vec3 outwardNormal(vec3 x, out vec3 color)
{
  vec3 g = (x - gridOrigin) / cellSize;
  float rho = kernelRadius / cellSize;
  ivec3 lo = max(ivec3(floor(g - rho)), ivec3(0));
  ivec3 hi = min(ivec3(floor(g + rho)), gridDims - 1);
  color = fluidColor;
  if (any(greaterThan(lo, hi)))
  {
    return vec3(0.0, 0.0, 1.0);
  }
  float inv2 = 1.0 / (kernelRadius * kernelRadius);
  vec3 toward = vec3(0.0);
  vec4 weighted = vec4(0.0);
  for (int z = lo.z; z <= hi.z; ++z)
  {
    for (int y = lo.y; y <= hi.y; ++y)
    {
      int row = (z * gridDims.y + y) * gridDims.x;
      int begin = int(texelFetch(cellStart, row + lo.x).r & 0x7fffffffu);
      int end = int(texelFetch(cellStart, row + hi.x + 1).r & 0x7fffffffu);
      for (int k = begin; k < end; ++k)
      {
        vec3 e = texelFetch(particles, k).xyz - x;
        float q = max(1.0 - dot(e, e) * inv2, 0.0);
        // grad phi is proportional to sum q^2 (x_j - x): it points into the fluid.
        toward += q * q * e;
#ifdef PARTICLE_COLORS
        weighted += q * q * q * vec4(texelFetch(particleColors, k).rgb, 1.0);
#endif
      }
    }
  }
  color = weighted.w > 0.0 ? weighted.rgb / weighted.w : fluidColor;
  float len = length(toward);
  return len > 0.0 ? -toward / len : vec3(0.0, 0.0, 1.0);
}

// Ray parameter where the ray leaves the box [lo, hi] (cell indices) [model units].
float boxExit(vec3 O, vec3 invD, ivec3 lo, ivec3 hi)
{
  vec3 a = (gridOrigin + vec3(lo) * cellSize - O) * invD;
  vec3 b = (gridOrigin + vec3(hi) * cellSize - O) * invD;
  vec3 far = max(a, b);
  return min(min(far.x, far.y), far.z);
}

// Secant/bisection between t0 (phi on the `inside` = false side) and t1 (on the other side).
float refine(vec3 O, vec3 D, float t0, float t1, bool entering)
{
  float f0 = -1.0, f1 = -1.0; // unknown until sampled
  for (int i = 0; i < (entering ? 5 : 6); ++i)
  {
    float tm = 0.5 * (t0 + t1);
    float fm = phiAt(O + D * tm);
    if ((fm >= isoValue) == entering)
    {
      t1 = tm;
      f1 = fm;
    }
    else
    {
      t0 = tm;
      f0 = fm;
    }
  }
  if (f0 >= 0.0 && f1 >= 0.0 && f1 != f0)
  {
    return mix(t0, t1, clamp((isoValue - f0) / (f1 - f0), 0.0, 1.0));
  }
  return 0.5 * (t0 + t1);
}

// March from t to tEnd; returns the ray parameter where phi first crosses the iso value
// (entering: rising through it, else falling), or -1. Entering, the samples lie on the lattice
// tOrigin + k stepLength whatever was skipped (empty cells and blocks, spans outside the splats),
// so skipping only leaves out samples where phi is below the iso value and finds the very hit
// the brute-force march finds.
float march(vec3 O, vec3 D, float t, float tEnd, bool entering, float tOrigin)
{
  vec3 invD = 1.0 / vec3(abs(D.x) > 1e-20 ? D.x : 1e-20, abs(D.y) > 1e-20 ? D.y : 1e-20, abs(D.z) > 1e-20 ? D.z : 1e-20);
  float tPrev = t;
  if (entering)
  {
    t = tOrigin + ceil((t - tOrigin) / stepLength) * stepLength;
    tPrev = t - stepLength;
  }
  int budget = samples + maxSteps;
  for (int iteration = 0; iteration < 8 * maxSteps && t < tEnd && samples < budget; ++iteration)
  {
    vec3 x = O + D * t;
    if (entering && skipping != 0)
    {
      ivec3 c = clamp(ivec3(floor((x - gridOrigin) / cellSize)), ivec3(0), gridDims - 1);
      ivec3 b = c / blockCells;
      float tExit = -1.0;
      if (texelFetch(blockOccupied, (b.z * blockDims.y + b.y) * blockDims.x + b.x).r == 0u)
      {
        tExit = boxExit(O, invD, b * blockCells, (b + 1) * blockCells);
      }
      else if ((texelFetch(cellStart, (c.z * gridDims.y + c.y) * gridDims.x + c.x).r & 0x80000000u) == 0u)
      {
        tExit = boxExit(O, invD, c, c + 1);
      }
      if (tExit >= 0.0)
      {
        // On to the first lattice sample past the empty box (at least one step on).
        t = max(tOrigin + ceil((tExit - tOrigin) / stepLength) * stepLength, t + stepLength);
        tPrev = t - stepLength;
        continue;
      }
    }
    if ((phiAt(x) >= isoValue) == entering)
    {
      return refine(O, D, tPrev, t, entering);
    }
    tPrev = t;
    // Inside, the march only looks for where the fluid ends (for the path length): it strides
    // eight steps at a time and the refinement finds the exit within a 64th of that.
    t += entering ? stepLength : 8.0 * stepLength;
  }
  return -1.0;
}

// Eye distance of the opaque scene at viewport pixel p (a huge value over the background).
float opaqueDistance(vec2 p)
{
  float w = texelFetch(opaqueDepthTex, ivec2(clamp(p, vec2(0.0), viewportSize - 1.0)), 0).r;
  if (w >= 1.0)
  {
    return 1e30;
  }
  float ndc = 2.0 * w - 1.0;
  return parallelProjection != 0 ? -(ndc - depthCoefficients.y) / depthCoefficients.x
                                 : depthCoefficients.y / (ndc + depthCoefficients.x);
}

vec2 toViewportPixel(vec3 eye)
{
  vec4 clip = VCDCMatrix * vec4(eye, 1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * viewportSize;
}

#ifdef SPLAT_BOUNDS
// Ray parameter [model units] where the ray of viewport pixel `pixel` reaches view depth z.
float tAtDepth(vec2 pixel, vec3 O, vec3 D, float z)
{
  vec3 m = (eyeToModel * vec4(eyePosition(pixel, z), 1.0)).xyz;
  return dot(m - O, D);
}

// The ray's span [t0, t1] between view depths near and far, within [tNear, tFar]; empty (t0 > t1)
// where no sphere lies.
vec2 spanOf(vec2 pixel, vec3 O, vec3 D, float near, float far, float tNear, float tFar)
{
  if (near > 1e29)
  {
    return vec2(1e30, -1e30);
  }
  return vec2(max(tAtDepth(pixel, O, D, near), tNear), min(tAtDepth(pixel, O, D, far), tFar));
}
#endif

void main()
{
  vec2 pixel = (floor(texCoord * vec2(marchSize)) + 0.5) * pixelScale;
  // The eye ray through the pixel, then into model coordinates.
  vec3 originVC = parallelProjection != 0 ? eyePosition(pixel, 0.0) : vec3(0.0);
  vec3 dirVC = parallelProjection != 0 ? vec3(0.0, 0.0, -1.0) : normalize(eyePosition(pixel, 1.0));
  vec3 O = (eyeToModel * vec4(originVC, 1.0)).xyz;
  vec3 D = normalize(mat3(eyeToModel) * dirVC);
  // The grid's box, cut at the opaque scene.
  vec3 boxLo = gridOrigin, boxHi = gridOrigin + vec3(gridDims) * cellSize;
  vec3 invD = 1.0 / vec3(abs(D.x) > 1e-20 ? D.x : 1e-20, abs(D.y) > 1e-20 ? D.y : 1e-20, abs(D.z) > 1e-20 ? D.z : 1e-20);
  vec3 a = (boxLo - O) * invD, b = (boxHi - O) * invD;
  float tNear = max(max(min(a.x, b.x), min(a.y, b.y)), max(min(a.z, b.z), 0.0));
  float tFar = min(min(max(a.x, b.x), max(a.y, b.y)), max(a.z, b.z));
  float opaque = opaqueDistance(pixel);
  if (opaque < 1e29)
  {
    vec3 opaqueModel = (eyeToModel * vec4(originVC + dirVC * (parallelProjection != 0 ? opaque : opaque / -dirVC.z), 1.0)).xyz;
    tFar = min(tFar, dot(opaqueModel - O, D));
  }
  if (tNear >= tFar)
  {
    discard;
  }
#ifdef SPLAT_BOUNDS
  vec4 bounds = texelFetch(boundsTex, ivec2(floor(texCoord * vec2(marchSize))) / BOUNDS_PIXELS, 0);
  vec2 first = spanOf(pixel, O, D, bounds.x, -bounds.y, tNear, tFar);
  vec2 second = spanOf(pixel, O, D, bounds.z, -bounds.w, tNear, tFar);
  if (second.x < first.x)
  {
    vec2 swap = first;
    first = second;
    second = swap;
  }
  if (second.x <= first.y)
  {
    first.y = max(first.y, second.y); // overlapping: one span
    second = vec2(1e30, -1e30);
  }
  if (first.x >= first.y && second.x >= second.y)
  {
    discard; // no sphere over this pixel in front of the opaque scene: nothing to march
  }
  float tHit = first.x < first.y ? march(O, D, first.x, first.y, true, tNear) : -1.0;
  if (tHit < 0.0 && second.x < second.y)
  {
    tHit = march(O, D, second.x, second.y, true, tNear);
  }
#else
  float tHit = march(O, D, tNear, tFar, true, tNear);
#endif
  if (displayMode == 3)
  {
    // Steps: red counts the samples of phi (one level each, up to 255), green shows up to 64.
    if (samples == 0)
    {
      discard;
    }
    vec4 hitClip = VCDCMatrix * modelToEye * vec4(O + D * max(tHit, 0.0), 1.0);
    gl_FragDepth = tHit >= 0.0 ? clamp(0.5 * hitClip.z / hitClip.w + 0.5, 0.0, 1.0) : 1.0;
    gl_FragData[0] = vec4(float(min(samples, 255)) / 255.0, min(float(samples) / 64.0, 1.0), 0.0, 1.0);
#ifdef LOW_RESOLUTION
    gl_FragData[1] = vec4(gl_FragDepth, 0.0, 0.0, 1.0);
#endif
    return;
  }
  if (tHit < 0.0)
  {
    discard;
  }
  vec3 P = O + D * tHit;
  vec3 eyeP = (modelToEye * vec4(P, 1.0)).xyz;
  vec4 clip = VCDCMatrix * vec4(eyeP, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  vec3 particleColor;
  vec3 Nm = outwardNormal(P, particleColor);
  vec3 N = normalize(transpose(mat3(eyeToModel)) * Nm); // normals transform by the inverse transpose
  vec3 V = -dirVC;
  if (displayMode == 2)
  {
    gl_FragData[0] = vec4(0.5 + 0.5 * N, 1.0);
#ifdef LOW_RESOLUTION
    gl_FragData[1] = vec4(gl_FragDepth, 0.0, 0.0, 1.0);
#endif
    return;
  }
  vec3 base = fluidColor;
#ifdef PARTICLE_COLORS
  base = mix(base, particleColor, colorMix);
#endif
  float fresnel = schlickFresnel(dot(N, V), refractiveIndex);
  vec3 reflected = environmentColor(reflect(-V, N));
  vec3 diffuse = vec3(ambient);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < lightCount; ++i)
  {
    vec3 L = -lightDirectionVC[i];
    diffuse += max(dot(N, L), 0.0) * lightColor[i];
    specular += pow(max(dot(N, normalize(L + V)), 0.0), shininess) * lightColor[i];
  }
  specular *= specularStrength;
  vec3 color;
#ifdef TRANSPARENT_FLUID
  // Into the fluid by Snell's law, along the refracted ray to where phi falls below the iso value.
  vec3 T = refract(D, Nm, 1.0 / refractiveIndex);
  float tOut = march(P, T, 0.25 * stepLength, 1e30, false, 0.0);
  float path = 0.0;
  vec3 behind;
  if (tOut < 0.0)
  {
    // No exit within MaxSteps: as thick as the steps went; the light behind is the fluid's own.
    path = float(maxSteps) * stepLength;
    behind = base;
  }
  else
  {
    path = tOut;
    vec3 E = P + T * tOut;
    vec3 unused;
    vec3 exitNormal = outwardNormal(E, unused);
    vec3 leaving = refract(T, -exitNormal, refractiveIndex);
    bool reflected = dot(leaving, leaving) == 0.0; // total internal reflection
    if (reflected)
    {
      leaving = reflect(T, -exitNormal);
    }
    vec3 eyeE = (modelToEye * vec4(E, 1.0)).xyz;
    vec3 outVC = normalize(mat3(modelToEye) * leaving);
    vec2 q = toViewportPixel(eyeE);
    float there = opaqueDistance(q);
    float gap = there - (-eyeE.z); // from the exit to the opaque surface behind it, along the view
    if (there < 1e29 && gap < kernelRadius)
    {
      // The fluid rests on the opaque surface there (no air between them, so no reflection
      // inside either): what lies at the exit.
      behind = texelFetch(opaqueColor, ivec2(clamp(q, vec2(0.0), viewportSize - 1.0)), 0).rgb;
    }
    else if (there > 1e29 || reflected)
    {
      // Nothing opaque behind, or the light comes back into the fluid (one internal bounce is
      // not followed): the environment the ray leaves toward.
      behind = environmentColor(outVC);
    }
    else
    {
      // Follow the exiting ray to the opaque surface's depth at the exit (first order).
      float s = gap / max(-outVC.z, 0.25);
      vec2 r = clamp(toViewportPixel(eyeE + outVC * s), vec2(0.0), viewportSize - 1.0);
      behind = texelFetch(opaqueColor, ivec2(r), 0).rgb;
    }
  }
  vec3 sigma = -log(max(base, vec3(1e-3))) / attenuationDistance;
  color = mix(behind * exp(-sigma * path), reflected, fresnel) + specular;
#else
  color = base * diffuse * (1.0 - fresnel) + fresnel * reflected + specular;
#endif
  gl_FragData[0] = vec4(clamp(color, 0.0, 1.0), 1.0);
#ifdef LOW_RESOLUTION
  gl_FragData[1] = vec4(gl_FragDepth, 0.0, 0.0, 1.0);
#endif
}
