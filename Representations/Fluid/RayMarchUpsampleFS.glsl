//=========================================================================
// ParaFluid ray-marched fluid at reduced resolution: each viewport pixel blends the 4 nearest
// marched pixels bilinearly, leaving out those behind the opaque scene at this pixel and weighting
// down those far in depth from the nearest (so colours do not bleed across depth edges); a pixel
// is fluid where the marched pixels covering it carry at least half the bilinear weight.
//=========================================================================
uniform sampler2D lowColor;  // rgb, a = 1 where a ray hit
uniform sampler2D lowDepth;  // window depth of the hit
uniform sampler2D opaqueDepthTex;
uniform ivec2 lowSize;
uniform float pixelScale;    // viewport pixels per marched pixel
uniform float depthTolerance; // window-depth difference that halves a sample's weight

//VTK::Output::Dec

void main()
{
  ivec2 p = targetPixel();
  float opaque = texelFetch(opaqueDepthTex, p, 0).r;
  vec2 u = (vec2(p) + 0.5) / pixelScale - 0.5;
  ivec2 i0 = ivec2(floor(u));
  vec2 f = u - vec2(i0);
  float nearest = 2.0;
  vec4 c[4];
  float z[4], w[4];
  for (int k = 0; k < 4; ++k)
  {
    ivec2 q = clamp(i0 + ivec2(k & 1, k >> 1), ivec2(0), lowSize - 1);
    c[k] = texelFetch(lowColor, q, 0);
    z[k] = texelFetch(lowDepth, q, 0).r;
    w[k] = ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k >> 1) != 0 ? f.y : 1.0 - f.y);
    if (c[k].a <= 0.0 || z[k] > opaque)
    {
      w[k] = 0.0;
    }
    else
    {
      nearest = min(nearest, z[k]);
    }
  }
  float coverage = w[0] + w[1] + w[2] + w[3];
  if (coverage < 0.5)
  {
    discard;
  }
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    float wk = w[k] / (1.0 + abs(z[k] - nearest) / depthTolerance);
    sum += wk * c[k].rgb;
    total += wk;
  }
  gl_FragDepth = nearest;
  gl_FragData[0] = vec4(sum / total, 1.0);
}
