//=========================================================================
// ParaFluid toon fluid, 3/3: the across-edge DoG averaged along the edge, following the tangent
// of the smoothed structure tensor step by step (the flow-guided part of Kang et al.'s FDoG), then
// thresholded into a line coverage in [0, 1]: 1 where the averaged response is below -threshold.
//=========================================================================
uniform sampler2D tensorTex;
uniform sampler2D dogTex;
uniform float flowSigma; // pixels along the edge
uniform float threshold; // in line-image units (depth ranges)

//VTK::Output::Dec

vec2 tangentAt(vec2 x)
{
  vec3 t = texelFetch(tensorTex, ivec2(x), 0).xyz;
  float E = t.x, F = t.y, G = t.z;
  // Minor eigenvector: along the edge.
  float minor = 0.5 * (E + G - sqrt((E - G) * (E - G) + 4.0 * F * F));
  vec2 v = abs(E - minor) < abs(G - minor) ? vec2(minor - G, F) : vec2(F, minor - E);
  float n = length(v);
  return n > 1e-12 ? v / n : vec2(0.0, 1.0);
}

float response(vec2 x)
{
  ivec2 q = ivec2(x);
  if (any(lessThan(q, rectMin)) || any(greaterThanEqual(q, rectMax)))
  {
    return 0.0;
  }
  return texelFetch(dogTex, q, 0).r;
}

void main()
{
  ivec2 p = targetPixel();
  vec2 start = vec2(p) + 0.5;
  int steps = int(ceil(2.0 * flowSigma));
  float sum = response(start);
  float weights = 1.0;
  for (int side = -1; side <= 1; side += 2)
  {
    vec2 x = start;
    vec2 previous = tangentAt(start) * float(side);
    for (int k = 1; k <= steps; ++k)
    {
      vec2 t = tangentAt(x);
      t = dot(t, previous) < 0.0 ? -t : t; // keep walking the same way along the edge
      x += t;
      previous = t;
      float w = exp(-0.5 * float(k * k) / (flowSigma * flowSigma));
      sum += w * response(x);
      weights += w;
    }
  }
  float h = sum / weights;
  gl_FragData[0] = vec4(clamp((-h - threshold) / threshold, 0.0, 1.0), 0.0, 0.0, 0.0);
}
