//VTK::System::Dec
//=========================================================================
// ParaFluid screen-space fluid: the screen footprint of each particle's sphere, built from
// gl_VertexID (no vertex arrays): the particle's centre and radius come from a texture buffer.
// POINT_SPRITES defined: one point per particle, a square over the exact bounding box of the sphere's
// projection (one vertex instead of six: on a software rasteriser the vertex work of a million
// particles costs as much as their fill). The mapper uses it only when every centre is on screen
// (a point whose centre is clipped vanishes whole) and no point would exceed the largest size.
// Otherwise: a view-facing quad (six vertices) that covers the sphere's whole silhouette
// under perspective. Either way the fragment shader ray-traces the exact sphere.
//=========================================================================
uniform samplerBuffer particles; // xyz: model coordinates, w: radius (0: skip)
uniform samplerBuffer particleColors;
uniform int hasColors;
uniform mat4 MCVCMatrix;
uniform mat4 VCDCMatrix;
uniform int parallelProjection;
uniform float nearDistance;
uniform vec2 targetSize;  // pixels of the target drawn into
uniform vec4 projection;  // P00, P11, and P02, P12 (perspective) or P03, P13 (parallel)

#ifndef POINT_SPRITES
out vec3 quadVC;
#endif
flat out vec3 centreVC;
flat out float radiusVC;
flat out vec4 particleColor;
#ifdef THICKNESS_PASS
// Thickness of a particle smaller than 1.5 target pixels: its volume spread over the 2 x 2 pixels
// around its centre with bilinear weights (cloud in cell). Sampling so small a sphere's chord at
// pixel centres would alias against a lattice of particles (moire, and a mean off by tens of
// per cent); the deposit keeps every particle's volume, whatever its position against the pixels.
flat out int deposit;
flat out vec2 depositCentre; // target pixels
flat out float depositValue; // volume / pixel's world area: the thickness it adds
#endif

void main()
{
#ifdef POINT_SPRITES
  int particle = gl_VertexID;
#else
  int particle = gl_VertexID / 6;
  quadVC = vec3(0.0);
#endif
  int corner = gl_VertexID - 6 * particle;
  vec4 p = texelFetch(particles, particle);
  vec4 c = MCVCMatrix * vec4(p.xyz, 1.0);
  centreVC = c.xyz / c.w;
  radiusVC = p.w;
  particleColor = hasColors != 0 ? texelFetch(particleColors, particle) : vec4(1.0);

  vec2 k = vec2((corner == 1 || corner == 2 || corner == 4) ? 1.0 : -1.0,
                (corner == 2 || corner == 4 || corner == 5) ? 1.0 : -1.0);
  float r = radiusVC;
  if (!(r > 0.0) || centreVC.z - r > -nearDistance)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // skipped or wholly behind the near plane: clipped
    return;
  }
  // The quad lies in the plane z0 through the sphere's nearest point (or just past the near plane).
  float z0 = min(centreVC.z + r, -1.001 * nearDistance);
#ifdef THICKNESS_PASS
  deposit = 0;
  {
    // World size of one target pixel at the particle's depth.
    vec2 pixelWorld = 2.0 * (parallelProjection != 0 ? 1.0 : -centreVC.z) / (projection.xy * targetSize);
    if (r < 1.5 * min(pixelWorld.x, pixelWorld.y) && centreVC.z < -nearDistance)
    {
      deposit = 1;
      vec4 clip = VCDCMatrix * vec4(centreVC, 1.0);
      vec2 ndc = clip.xy / clip.w;
      depositCentre = (0.5 * ndc + 0.5) * targetSize;
      depositValue = 4.18879020479 * r * r * r / (pixelWorld.x * pixelWorld.y); // (4/3) pi r^3
      // A square of 2 pixels' side centred on the particle holds exactly the 4 pixel centres.
      gl_Position = vec4(ndc, clip.z / clip.w, 1.0);
#ifdef POINT_SPRITES
      gl_PointSize = 2.0;
#else
      gl_Position.xy += k * 2.0 / targetSize;
#endif
      return;
    }
  }
#endif
#ifdef POINT_SPRITES
  {
    // Bounding box of the projection in NDC. Perspective: per axis, the two planes through the
    // eye tangent to the sphere, x = k (-z), have k = (c d +- r sqrt(c^2 + d^2 - r^2)) / (d^2 - r^2)
    // with d = -centre.z (the mapper only takes this path when every sphere lies beyond its radius).
    vec2 lo, hi;
    if (parallelProjection != 0)
    {
      vec2 c = projection.xy * centreVC.xy + projection.zw;
      lo = c - projection.xy * r;
      hi = c + projection.xy * r;
    }
    else
    {
      float d = -centreVC.z;
      float q2 = d * d - r * r;
      vec2 root = r * sqrt(centreVC.xy * centreVC.xy + vec2(q2));
      vec2 kLo = (centreVC.xy * d - root) / q2;
      vec2 kHi = (centreVC.xy * d + root) / q2;
      lo = projection.xy * kLo - projection.zw;
      hi = projection.xy * kHi - projection.zw;
    }
    vec4 plane = VCDCMatrix * vec4(0.0, 0.0, z0, 1.0);
    gl_Position = vec4(0.5 * (lo + hi), plane.z / plane.w, 1.0);
    vec2 extent = 0.5 * (hi - lo) * targetSize;
    gl_PointSize = max(extent.x, extent.y);
  }
#else
  vec3 q;
  if (parallelProjection != 0)
  {
    q = vec3(centreVC.xy + k * r, z0);
  }
  else
  {
    // Silhouette cone: axis through the centre, half angle alpha; phi is the axis' angle to the
    // view direction. Its section by the plane z0 lies within s of where the axis meets it.
    float L = length(centreVC);
    float s;
    if (L <= r * 1.0001)
    {
      s = 1.0e4 * abs(z0); // the eye is inside the particle: cover everything
    }
    else
    {
      float alpha = asin(r / L);
      float phi = acos(clamp(-centreVC.z / L, -1.0, 1.0));
      float outer = min(phi + alpha, 1.5);
      s = abs(z0) * max(tan(outer) - tan(phi), tan(alpha) / cos(outer));
    }
    vec3 axisHit = centreVC * (z0 / centreVC.z);
    q = vec3(axisHit.xy + k * s, z0);
  }
  quadVC = q;
  gl_Position = VCDCMatrix * vec4(q, 1.0);
#endif
}
