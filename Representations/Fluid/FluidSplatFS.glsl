//VTK::System::Dec
//=========================================================================
// ParaFluid screen-space fluid: exact sphere impostor. The ray through the pixel is intersected
// with the particle's sphere; misses are discarded. Depth pass (thicknessPass = 0): writes the
// eye-space distance -z of the front hit (0 means no fluid) and the window depth, and the
// particle's colour in a second target. Thickness pass: adds the chord length through the sphere
// (additive blending, no depth test; at half resolution). Both drop fragments behind the opaque
// scene.
//=========================================================================
uniform mat4 VCDCMatrix;
uniform int parallelProjection;
uniform int thicknessPass;
uniform int useOpaqueDepth;
uniform sampler2D opaqueDepth;
uniform float opaqueDepthScale; // full-resolution pixels per pixel of this pass

in vec3 quadVC;
flat in vec3 centreVC;
flat in float radiusVC;
flat in vec4 particleColor;

//VTK::Output::Dec

void main()
{
  vec3 origin = vec3(0.0);
  vec3 dir = normalize(quadVC);
  if (parallelProjection != 0)
  {
    origin = vec3(quadVC.xy, centreVC.z + 2.0 * radiusVC);
    dir = vec3(0.0, 0.0, -1.0);
  }
  vec3 oc = origin - centreVC;
  float b = dot(dir, oc);
  float h = b * b - (dot(oc, oc) - radiusVC * radiusVC);
  if (h < 0.0)
  {
    discard;
  }
  h = sqrt(h);
  vec3 hit = origin + (-b - h) * dir;
  vec4 clip = VCDCMatrix * vec4(hit, 1.0);
  float windowDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  if (useOpaqueDepth != 0 && windowDepth >= texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy * opaqueDepthScale), 0).r)
  {
    discard;
  }
  gl_FragDepth = windowDepth;
  if (thicknessPass != 0)
  {
    gl_FragData[0] = vec4(2.0 * h, 0.0, 0.0, 0.0);
  }
  else
  {
    gl_FragData[0] = vec4(-hit.z, 0.0, 0.0, 0.0);
    gl_FragData[1] = particleColor;
  }
}
