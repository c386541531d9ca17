//=========================================================================
// ParaFluid Volumetric Cloud: one ray per pixel through a 3-D texture of density, lit the way a
// cloud is (not by a transfer function). Along the ray (Hillaire 2016, "Physically based sky,
// atmosphere and cloud rendering in Frostbite"):
//  - extinction sigma_t = extinction x density, Beer-Lambert transmittance over each step, with
//    the step's in-scattering integrated analytically (S (1 - exp(-sigma_t dt)) / sigma_t);
//  - single scattering of the sun (or key light) with a two-lobe Henyey-Greenstein phase
//    function, shadowed by the density between the sample and the light (a precomputed volume:
//    the path toward the light in .r, toward the sky in .g, in density x m);
//  - optionally, multiple scattering by octaves of fainter, less directional, less absorbed light
//    (Wrenninge, Kulla & Lundqvist 2013), and the "powder" darkening of edges facing the light
//    (Schneider & Vos 2015);
//  - light paths read with an extinction no higher than the grid resolves (the densest voxel
//    2 optical depths deep): in thicker media the light within a voxel of the surface, which
//    the lit side shows, would otherwise be taken from the voxel's centre, many optical depths
//    in, and the cloud drawn black; a semi-infinite cloud's surface looks the same whatever its
//    extinction (single scattering off a half-space, albedo x phase x mu0 / (mu0 + mu));
//  - ambient sky light, dimmed by the density above the sample as diffuse light fades in a
//    scattering medium, exp(-sqrt(3 (1 - albedo) (1 - g)) tau) (the diffusion approximation of
//    radiative transfer, e.g. Bohren 1987), by the same octaves;
//  - a start jittered per pixel (interleaved gradient noise, Jimenez 2014) against banding,
//    steps that grow through thin air and step back to the fine stride where they land in
//    cloud (so an edge is never integrated over a long stride), steps that shrink where one
//    would cross an optical depth over 1/2 (thick smoke is lit at its surface), a jump over
//    empty blocks (a coarse grid of the density's maxima), and an early exit once the
//    transmittance is below minTransmittance;
//  - the ray stops at the opaque scene's depth, and the result is premultiplied: the view's
//    colour behind is kept in proportion to the transmittance (blend ONE, ONE_MINUS_SRC_ALPHA);
//    under MPI it also writes the depth where it starts to scatter, so that ParaView's depth
//    compositing keeps it over other processes' background.
//=========================================================================
in vec2 texCoord;

uniform sampler3D densityTex;   // the density
uniform sampler3D lightTex;     // density path toward the light (.r) and the sky (.g) [density x m]
uniform sampler3D blockTex;     // the largest density a block's samples blend
uniform sampler2D opaqueDepthTex;
uniform mat4 dcToWorld;         // inverse of world -> clip (key form)
uniform vec2 viewportSize;
uniform vec3 boxMin;            // the volume's world box
uniform vec3 boxMax;
uniform vec3 blockCount;        // blocks per axis
uniform float extinction;       // per unit density [1/m]
uniform float lightExtinction;  // the extinction the light paths are read with: at most what
                                // makes the densest voxel 2 deep (a denser cloud is lit at its
                                // surface, which the grid cannot resolve: it is lit as that one)
uniform float albedo;           // scattering over extinction
uniform float stepLength;       // [m]
uniform int maxSteps;
uniform float minTransmittance;
uniform float emptyDensity;     // a block whose largest density is below this is skipped
uniform vec3 lightDirection;    // toward the light, unit
uniform vec3 lightColor;
uniform vec3 skyColor;
uniform float anisotropy;       // forward lobe g
uniform int shadows;
uniform int octaves;            // 1: single scattering
uniform float powder;           // 0..1
uniform float diffuseDecay;     // sqrt(3 (1 - albedo) (1 - g)): how fast diffuse light fades with optical depth
uniform int displayMode;        // 0 lit, 1 samples per pixel
uniform int writeDepth;         // under MPI: the depth of the first sample that scatters, so that
                                // depth compositing across processes keeps the cloud
uniform mat4 worldToClip;       // (key form)

//VTK::Output::Dec

const float PI = 3.14159265;
// The optical depth one step may cross, and the shortest step (in steps) taken to keep to it.
const float maxStepDepth = 0.5;
const float minStepFraction = 1.0 / 16.0;

float henyeyGreenstein(float cosTheta, float g)
{
  float d = 1.0 + g * g - 2.0 * g * cosTheta;
  return (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
}

// Two lobes: mostly forward (the silver lining toward the sun), some backward (after Hillaire
// 2016's dual-lobe mix).
float phase(float cosTheta, float g)
{
  return mix(henyeyGreenstein(cosTheta, -0.5 * g), henyeyGreenstein(cosTheta, g), 0.7);
}

vec3 toTexture(vec3 p)
{
  return (p - boxMin) / (boxMax - boxMin);
}

// Where the ray o + t d leaves the box [lo, hi] (t beyond tEnter).
vec2 boxSpan(vec3 o, vec3 d, vec3 lo, vec3 hi)
{
  vec3 inv = 1.0 / d;
  vec3 a = (lo - o) * inv;
  vec3 b = (hi - o) * inv;
  vec3 tMin = min(a, b);
  vec3 tMax = max(a, b);
  return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

void main()
{
  vec2 ndc = texCoord * 2.0 - 1.0; // the quad covers the renderer's viewport
  vec4 nearH = dcToWorld * vec4(ndc, -1.0, 1.0);
  vec4 farH = dcToWorld * vec4(ndc, 1.0, 1.0);
  vec3 origin = nearH.xyz / nearH.w;
  vec3 dir = normalize(farH.xyz / farH.w - origin);
  // The opaque scene's distance along the ray.
  float depth = texelFetch(opaqueDepthTex, ivec2(texCoord * viewportSize), 0).r;
  vec4 opaqueH = dcToWorld * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  float tOpaque = dot(opaqueH.xyz / opaqueH.w - origin, dir);

  // A direction component of exactly 0 would divide by zero in the slab test.
  vec3 d = dir;
  d.x = abs(d.x) < 1e-8 ? 1e-8 : d.x;
  d.y = abs(d.y) < 1e-8 ? 1e-8 : d.y;
  d.z = abs(d.z) < 1e-8 ? 1e-8 : d.z;
  vec2 span = boxSpan(origin, d, boxMin, boxMax);
  float t = max(span.x, 0.0);
  float tEnd = min(span.y, tOpaque);
  if (t >= tEnd)
  {
    discard;
  }
  float jitter = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  float cosTheta = dot(dir, lightDirection);
  vec3 blockSize = (boxMax - boxMin) / blockCount;

  float transmittance = 1.0;
  float tFirst = -1.0;
  vec3 radiance = vec3(0.0);
  int samples = 0;
  float step = stepLength;
  for (int i = 0; i < maxSteps && t < tEnd; ++i)
  {
    vec3 p = origin + (t + 1e-4 * stepLength) * d;
    vec3 block = clamp(floor((p - boxMin) / blockSize), vec3(0.0), blockCount - 1.0);
    if (texelFetch(blockTex, ivec3(block), 0).r < emptyDensity)
    {
      // Nothing here can scatter or absorb: on to where the ray leaves this block.
      vec2 inBlock = boxSpan(origin, d, boxMin + block * blockSize, boxMin + (block + 1.0) * blockSize);
      t = max(inBlock.y, t + 1e-4 * stepLength);
      continue;
    }
    float dt = min(step, tEnd - t);
    // The sample lies at a jittered place within its segment: the segments still tile the ray.
    vec3 q = origin + (t + jitter * dt) * d;
    vec3 uvw = toTexture(q);
    float rho = texture(densityTex, uvw).r;
    ++samples;
    if (rho > 0.0 && step > stepLength)
    {
      // A long stride reached cloud: march this segment again at the fine stride.
      step = stepLength;
      continue;
    }
    float sigmaT = extinction * rho;
    if (sigmaT * dt > maxStepDepth && dt > minStepFraction * stepLength)
    {
      // So dense that one step would hide most of itself: the light read at the sample would be
      // that of a random depth inside the step (dark specks at the edge of thick smoke). March this
      // segment again in steps that each cross at most maxStepDepth.
      step = max(maxStepDepth / sigmaT, minStepFraction * stepLength);
      continue;
    }
    if (rho > 0.0)
    {
      tFirst = tFirst < 0.0 ? t : tFirst;
      vec2 paths = shadows != 0 ? texture(lightTex, uvw).rg : vec2(0.0);
      // Octave k: a^k of the optical depth, b^k of the light, c^k of the anisotropy (a = b = c = 1/2).
      // The sky light (isotropic) by the same octaves.
      vec3 sun = vec3(0.0);
      vec3 sky = vec3(0.0);
      float weight = 1.0, depthScale = 1.0, g = anisotropy;
      for (int k = 0; k < octaves; ++k)
      {
        sun += weight * exp(-lightExtinction * paths.r * depthScale) * phase(cosTheta, g) * lightColor;
        sky += weight * exp(-diffuseDecay * lightExtinction * paths.g * depthScale) * skyColor;
        weight *= 0.5;
        depthScale *= 0.5;
        g *= 0.5;
      }
      sun *= mix(1.0, 1.0 - exp(-2.0 * lightExtinction * paths.r), powder);
      vec3 scattered = albedo * sigmaT * (sun + sky);
      float stepDepth = sigmaT * dt;
      float stepTransmittance = exp(-stepDepth);
      // The length over which the step scatters, (1 - exp(-sigma_t dt)) / sigma_t: its series where
      // sigma_t is tiny (at a plume's fringe extinction x density fell below the smallest normal
      // float, llvmpipe flushed it to 0, and this was 0 / 0: NaN pixels drawn black).
      float scatterLength = stepDepth > 1e-4 ? (1.0 - stepTransmittance) / sigmaT : dt * (1.0 - 0.5 * stepDepth);
      radiance += transmittance * scattered * scatterLength;
      transmittance *= stepTransmittance;
      step = min(stepLength, maxStepDepth / sigmaT);
      if (transmittance < minTransmittance)
      {
        break;
      }
    }
    else
    {
      // Thin air: longer strides, up to twice the step (four times jumped thin wisps, and with the
      // jitter's pattern drew cross-hatching in thin cloud).
      step = min(2.0 * step, 2.0 * stepLength);
    }
    t += dt;
  }
  gl_FragDepth = gl_FragCoord.z;
  if (writeDepth != 0 && tFirst >= 0.0)
  {
    vec4 clip = worldToClip * vec4(origin + tFirst * d, 1.0);
    gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  }
  if (displayMode == 1)
  {
    gl_FragData[0] = vec4(float(min(samples, 255)) / 255.0, 0.0, 0.0, 1.0);
    return;
  }
  float alpha = 1.0 - transmittance;
  if (alpha <= 0.0 && samples == 0)
  {
    discard;
  }
  gl_FragData[0] = vec4(radiance, alpha);
}
