//=========================================================================
// ParaFluid toon fluid, 2/3: difference of Gaussians across the edge (Kang, Lee & Chui 2007,
// "Coherent line drawing"): along the gradient direction of the smoothed structure tensor, the
// line image convolved with G(sigma) - G(1.6 sigma). Negative on the near side of a depth step and
// of a silhouette. (Kang et al. weight the surround by rho = 0.99 for intensities in [0, 1]; depth
// is unbounded, and any rho < 1 would make the response depend on how far the fluid is.)
//=========================================================================
uniform sampler2D tensorTex;
uniform float lineDepthScale;
uniform float backgroundValue;
uniform float sigma; // pixels: the line's width

//VTK::Output::Dec

float lineImage(ivec2 q)
{
  float d = fetchDepth(q);
  return d > 0.0 ? d * lineDepthScale : backgroundValue;
}

// Unit gradient direction: the major eigenvector of the tensor (E F; F G).
vec2 gradientDirection(vec3 t)
{
  float E = t.x, F = t.y, G = t.z;
  float major = 0.5 * (E + G + sqrt((E - G) * (E - G) + 4.0 * F * F));
  vec2 v = abs(E - major) < abs(G - major) ? vec2(major - G, F) : vec2(F, major - E);
  float n = length(v);
  return n > 1e-12 ? v / n : vec2(1.0, 0.0);
}

void main()
{
  ivec2 p = targetPixel();
  vec2 g = gradientDirection(texelFetch(tensorTex, p, 0).xyz);
  float sigmaS = 1.6 * sigma;
  int reach = int(ceil(2.0 * sigmaS));
  float centre = 0.0, surround = 0.0, wc = 0.0, ws = 0.0;
  for (int k = -reach; k <= reach; ++k)
  {
    float t = float(k);
    float v = lineImage(p + ivec2(round(t * g)));
    float a = exp(-0.5 * t * t / (sigma * sigma));
    float b = exp(-0.5 * t * t / (sigmaS * sigmaS));
    centre += a * v;
    surround += b * v;
    wc += a;
    ws += b;
  }
  gl_FragData[0] = vec4(centre / wc - surround / ws, 0.0, 0.0, 0.0);
}
