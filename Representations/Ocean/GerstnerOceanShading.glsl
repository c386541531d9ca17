//=========================================================================
// ParaFluid Gerstner ocean: shading of the water surface (fragment shader). Linear HDR radiance:
// body colour by depth (refracted light), environment reflection weighted by Schlick's Fresnel
// term (R0 = 0.02 for air to water), sun specular, foam; then exposure tone mapping and gamma.
// OCEAN_CUBEMAP: oceanEnvironment is a cube map (+Y up in its own frame, world +Z up);
// otherwise a procedural sky with a sun. oceanRipples: tileable tangent-space normal map.
//=========================================================================

vec3 oceanSky(vec3 d)
{
#ifdef OCEAN_CUBEMAP
  return texture(oceanEnvironment, vec3(d.x, d.z, -d.y)).rgb * oceanEnvironmentScale;
#else
  float up = max(d.z, 0.0);
  vec3 sky = mix(oceanHorizonColor, oceanZenithColor, pow(up, 0.45));
  if (d.z < 0.0)
  {
    sky = oceanHorizonColor * 0.55; // below the horizon: the far sea and haze
  }
  float sun = max(dot(d, oceanSunDirection), 0.0);
  // A sun disk about 0.5 degrees across, 60 times the sky's radiance, and its glow.
  sky += oceanSunColor * (60.0 * step(0.99996, sun) + 0.25 * pow(sun, 12.0));
  return sky;
#endif
}

// Tangent-space ripple normal from two samples of the tileable map at unrelated scales, angles
// and drift directions, so the tiling does not show.
vec3 oceanRippleNormal(vec2 p)
{
  vec2 uv1 = p / oceanRippleScale + oceanRippleTime * vec2(0.021, 0.013);
  vec2 q = mat2(0.8, 0.6, -0.6, 0.8) * p;
  vec2 uv2 = q / (1.73 * oceanRippleScale) + oceanRippleTime * vec2(-0.017, 0.023);
  vec3 n1 = texture(oceanRipples, uv1).xyz * 2.0 - 1.0;
  vec3 n2 = texture(oceanRipples, uv2).xyz * 2.0 - 1.0;
  vec3 n = vec3(n1.xy + n2.xy, n1.z * n2.z);
  return normalize(vec3(n.xy * oceanRippleStrength, max(n.z, 1e-3)));
}

vec3 oceanShade(vec3 world, vec3 eye, vec2 rest, vec3 dx, vec3 dy, float foam, float depth)
{
  vec3 tx = vec3(1.0 + dx.x, dx.y, dx.z);
  vec3 ty = vec3(dy.x, 1.0 + dy.y, dy.z);
  vec3 N = normalize(cross(tx, ty));
  vec3 V = normalize(eye - world);
  // Ripples fade out with distance, where they would only alias.
  float fade = clamp(1.0 - length(eye - world) / oceanRippleFade, 0.0, 1.0);
  if (oceanRippleStrength > 0.0 && fade > 0.0)
  {
    vec3 r = oceanRippleNormal(rest);
    vec3 T = normalize(tx);
    vec3 B = normalize(cross(N, T));
    T = cross(B, N);
    N = normalize(mix(N, T * r.x + B * r.y + N * r.z, fade));
  }
  if (dot(N, V) < 0.0)
  {
    N = normalize(N - 1.01 * dot(N, V) * V); // seen at grazing angles past a crest: face the eye
  }
  float cosine = max(dot(N, V), 0.0);
  float fresnel = 0.02 + 0.98 * pow(1.0 - cosine, 5.0);
  vec3 R = reflect(-V, N);
  vec3 reflected = oceanSky(R);
  // Water body: shallow colour fading to deep colour over oceanColorDepth metres of water.
  float shallow = exp(-depth / oceanColorDepth); // depth is 1e6 in deep water
  vec3 body = mix(oceanDeepColor, oceanShallowColor, shallow);
  vec3 L = oceanSunDirection;
  float lit = 0.35 + 0.65 * max(dot(N, L), 0.0);
  vec3 transmitted = body * lit * oceanSunIntensity;
  vec3 specular = oceanSunColor * oceanSunIntensity * pow(max(dot(R, L), 0.0), oceanShininess) * fresnel * 4.0;
  vec3 color = (1.0 - fresnel) * transmitted + fresnel * reflected + specular;
  color = mix(color, oceanFoamColor * lit * oceanSunIntensity, foam * oceanFoamAmount);
  // Exposure tone mapping of the linear HDR radiance, then display gamma.
  vec3 mapped = vec3(1.0) - exp(-color * oceanExposure);
  return pow(mapped, vec3(1.0 / 2.2));
}
