//VTK::System::Dec
//=========================================================================
// ParaFluid screen-space fluid: one view-facing quad per particle, built from gl_VertexID (six
// vertices per particle, no vertex arrays): the particle's centre and radius come from a texture
// buffer. The quad covers the sphere's whole silhouette under perspective, so the fragment shader
// can ray-trace the exact sphere.
//=========================================================================
uniform samplerBuffer particles; // xyz: model coordinates, w: radius (0: skip)
uniform samplerBuffer particleColors;
uniform int hasColors;
uniform mat4 MCVCMatrix;
uniform mat4 VCDCMatrix;
uniform int parallelProjection;
uniform float nearDistance;

out vec3 quadVC;
flat out vec3 centreVC;
flat out float radiusVC;
flat out vec4 particleColor;

void main()
{
  int particle = gl_VertexID / 6;
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
}
