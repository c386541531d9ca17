//=========================================================================
// ParaFluid screen-space fluid: the final pass, drawn into the view's framebuffer with the depth
// test on, so the fluid composites with the opaque scene. Per pixel: eye position from the
// smoothed depth; normal from the neighbours (the one-sided difference with the smaller depth
// step at discontinuities); then the display mode's colour, and the surface's window depth.
// Shading: Schlick's Fresnel with R0 from the index of refraction; reflection of the environment
// (FluidLightingFS.glsl, prepended); Blinn-Phong specular from the view's lights; for
// transparent fluid, the opaque scene behind refracted by normal x thickness and attenuated by
// Beer-Lambert: transmission exp(-sigma t), sigma = -ln(fluidColor) / attenuationDistance, so a
// layer attenuationDistance thick tints white light to fluidColor.
//=========================================================================
uniform sampler2D thicknessTex; // reduced resolution, linear filtering
uniform vec2 thicknessScale;    // full-resolution pixel -> thickness texture coordinate
uniform sampler2D opaqueColor;
uniform sampler2D particleColorTex;
uniform int hasParticleColors;
uniform float colorMix;
uniform mat4 VCDCMatrix;
uniform int displayMode; // 0 opaque, 1 transparent, 2 normals, 3 thickness, 4 particle depth, 5 toon,
                         // 6 brush strokes (toon bands without lines; the strokes are drawn after)
uniform int toonBands;
uniform vec3 lineColor;
uniform float contourSpacing; // world units between depth contour lines; 0: none
uniform sampler2D linesTex;   // toon line coverage
uniform vec3 fluidColor;
uniform float attenuationDistance;
uniform float refractiveIndex;
uniform float refractionStrength;
uniform float shininess;
uniform float specularStrength;
uniform float ambient;
uniform vec2 depthRange; // particle depth mode: nearest and farthest distance of the fluid
uniform float silhouetteRadius; // particle radius [world units] the silhouette is smoothed over; 0: as splatted

//VTK::Output::Dec

// The neighbour difference with the smaller depth step (one-sided at discontinuities).
vec3 tangent(ivec2 p, vec3 centre, ivec2 step)
{
  float dm = fetchDepth(p - step);
  float dp = fetchDepth(p + step);
  vec3 m = eyePosition(vec2(p - step) + 0.5, dm);
  vec3 q = eyePosition(vec2(p + step) + 0.5, dp);
  bool hasM = dm > 0.0;
  bool hasP = dp > 0.0;
  if (hasM && hasP)
  {
    return abs(q.z - centre.z) < abs(centre.z - m.z) ? q - centre : centre - m;
  }
  if (hasP)
  {
    return q - centre;
  }
  if (hasM)
  {
    return centre - m;
  }
  return vec3(step, 0.0);
}

// Smoothed silhouettes. The splats' outline is a union of discs, scalloped one particle at a
// time. Its coverage blurred by a Gaussian of half a particle radius (48 taps on a Vogel spiral
// out to one radius, scaled by the radius in pixels at this depth, so the same at any zoom) is
// smooth, and its 0.5 level runs between the discs' tops and the notches between them: pixels
// below it are dropped (the tops), empty pixels above it are filled (the notches) with the depth
// of the fluid around them. A tap counts as covered when it holds fluid no more than `band`
// behind this pixel (fluid in front hides this surface's edge anyway, so a surface does not
// fray where a nearer one crosses it; fluid far behind is another surface, and this is its edge).
float silhouetteCoverage(ivec2 p, float d, float band, out float fill, out vec2 outward)
{
  outward = vec2(0.0);
  float radiusPx = silhouetteRadius / pixelFootprint(d > 0.0 ? d : depthRange.x).x;
  fill = d;
  if (d > 0.0)
  {
    // Well inside: fluid a radius away on all four sides.
    int r = int(radiusPx + 0.5);
    bool inside = true;
    for (int k = 0; k < 4 && inside; ++k)
    {
      ivec2 q = p + r * ivec2(k == 0 ? 1 : (k == 1 ? -1 : 0), k == 2 ? 1 : (k == 3 ? -1 : 0));
      float dq = fetchDepth(q);
      inside = dq > 0.0 && dq < d + band;
    }
    if (inside)
    {
      return 1.0;
    }
  }
  const int taps = 48;
  const float golden = 2.39996323; // radians
  float sigma2 = 0.25 * radiusPx * radiusPx;
  float covered = 0.0, total = 0.0, depthSum = 0.0, nearest = 1e30;
  for (int i = 0; i < taps; ++i)
  {
    float rho = radiusPx * sqrt((float(i) + 0.5) / float(taps));
    float angle = float(i) * golden;
    ivec2 q = p + ivec2(floor(rho * vec2(cos(angle), sin(angle)) + 0.5));
    float w = exp(-0.5 * rho * rho / max(sigma2, 1e-6));
    float dq = fetchDepth(q);
    total += w;
    if (dq > 0.0 && (d <= 0.0 || dq < d + band))
    {
      covered += w;
      depthSum += w * dq;
      nearest = min(nearest, dq);
    }
    else
    {
      outward += w * vec2(q - p);
    }
  }
  if (d <= 0.0 && covered > 0.0)
  {
    // An empty pixel takes the mean depth around it, or the nearest where surfaces differ.
    float mean = depthSum / covered;
    fill = mean - nearest < band ? mean : nearest;
  }
  return covered / total;
}

void main()
{
  ivec2 p = targetPixel();
  float d = fetchDepth(p);
  bool filled = false;
  vec2 outward = vec2(0.0);
  if (silhouetteRadius > 0.0)
  {
    float fill;
    if (silhouetteCoverage(p, d, 2.0 * silhouetteRadius, fill, outward) < 0.5)
    {
      discard;
    }
    filled = d <= 0.0;
    d = fill;
  }
  if (d <= 0.0)
  {
    discard;
  }
  vec3 P = eyePosition(vec2(p) + 0.5, d);
  vec3 N = normalize(cross(tangent(p, P, ivec2(1, 0)), tangent(p, P, ivec2(0, 1))));
  if (filled && dot(outward, outward) > 0.0)
  {
    // A filled notch of the silhouette faces outward, across the view, as the edge around it.
    N = normalize(vec3(normalize(outward), 0.35));
  }
  vec3 V = parallelProjection != 0 ? vec3(0.0, 0.0, 1.0) : normalize(-P);
  if (dot(N, V) < 0.0)
  {
    N = -N;
  }
  vec4 clip = VCDCMatrix * vec4(P, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);

  float thickness = displayMode == 1 || displayMode == 3 ? texture(thicknessTex, (vec2(p) + 0.5) * thicknessScale).r : 0.0;
  vec3 color;
  if (displayMode == 2)
  {
    color = 0.5 + 0.5 * N;
  }
  else if (displayMode == 3)
  {
    color = vec3(1.0 - exp(-thickness / attenuationDistance));
  }
  else if (displayMode == 4)
  {
    color = vec3(1.0 - clamp((d - depthRange.x) / max(depthRange.y - depthRange.x, 1e-12), 0.0, 1.0));
  }
  else
  {
    vec3 base = fluidColor;
    if (hasParticleColors != 0)
    {
      base = mix(base, texelFetch(particleColorTex, p, 0).rgb, colorMix);
    }
    float cosine = max(dot(N, V), 0.0);
    float fresnel = schlickFresnel(cosine, refractiveIndex);
    vec3 reflected = environmentColor(reflect(-V, N));
    vec3 diffuse = vec3(ambient);
    vec3 specular = vec3(0.0);
    float highlight = 0.0; // toon: the half-vector's closeness, with a broad fixed lobe
    for (int i = 0; i < lightCount; ++i)
    {
      vec3 L = -lightDirectionVC[i];
      diffuse += max(dot(N, L), 0.0) * lightColor[i];
      vec3 H = normalize(L + V);
      specular += pow(max(dot(N, H), 0.0), shininess) * lightColor[i];
      highlight = max(highlight, dot(N, H));
    }
    specular *= specularStrength;
    if (displayMode == 5 || displayMode == 6)
    {
      // Toon: the diffuse light's luminance quantised into toonBands levels of the fluid colour
      // (from 35 % to full), a hard highlight within about 14 degrees of the mirror direction
      // (a sharp specular lobe would break up on the particles' residual bumps), then lines.
      float lum = dot(diffuse, vec3(0.2126, 0.7152, 0.0722));
      float level = min(floor(lum * float(toonBands)), float(toonBands - 1)) / float(toonBands - 1);
      color = base * mix(0.35, 1.0, level);
      if (specularStrength > 0.0 && highlight > 0.97)
      {
        color = mix(color, vec3(1.0), 0.8);
      }
      float line = displayMode == 5 ? texelFetch(linesTex, p, 0).r : 0.0;
      if (displayMode == 5 && contourSpacing > 0.0)
      {
        // A contour wherever the quantised depth differs from the right or upper neighbour's.
        float band = floor(d / contourSpacing);
        float right = fetchDepth(p + ivec2(1, 0)), up = fetchDepth(p + ivec2(0, 1));
        if ((right > 0.0 && floor(right / contourSpacing) != band) || (up > 0.0 && floor(up / contourSpacing) != band))
        {
          line = 1.0;
        }
      }
      color = mix(color, lineColor, line);
    }
    else if (displayMode == 1)
    {
      vec2 offset = N.xy * thickness * refractionStrength / pixelFootprint(d);
      ivec2 q = clamp(ivec2(vec2(p) + offset), rectMin, rectMax - 1);
      vec3 behind = texelFetch(opaqueColor, q, 0).rgb;
      vec3 sigma = -log(max(base, vec3(1e-3))) / attenuationDistance;
      vec3 transmitted = behind * exp(-sigma * thickness);
      color = mix(transmitted, reflected, fresnel) + specular;
    }
    else
    {
      color = base * diffuse * (1.0 - fresnel) + fresnel * reflected + specular;
    }
  }
  gl_FragData[0] = vec4(clamp(color, 0.0, 1.0), 1.0);
}
