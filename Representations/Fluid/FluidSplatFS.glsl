//VTK::System::Dec
//=========================================================================
// ParaFluid screen-space fluid: exact sphere impostor. The ray through the pixel is intersected
// with the particle's sphere; misses are discarded. Depth pass (built without THICKNESS_PASS): writes the
// eye-space distance -z of the front hit (0 means no fluid) and the window depth, and the
// particle's colour in a second target. Thickness pass (THICKNESS_PASS): adds the chord length through the sphere
// (additive blending, no depth test; at reduced resolution). Both drop fragments behind the opaque
// scene.
//=========================================================================
uniform mat4 VCDCMatrix;
uniform int parallelProjection;
uniform int useOpaqueDepth;
uniform sampler2D opaqueDepth;
uniform float opaqueDepthScale; // full-resolution pixels per pixel of this pass
uniform vec2 targetSize;         // pixels of the target drawn into
uniform vec4 projection;         // P00, P11, and P02, P12 (perspective) or P03, P13 (parallel)

#ifndef POINT_SPRITES
in vec3 quadVC;
#endif
flat in vec3 centreVC;
flat in float radiusVC;
flat in vec4 particleColor;
#ifdef THICKNESS_PASS
flat in int deposit;
flat in vec2 depositCentre;
flat in float depositValue;
#endif

//VTK::Output::Dec

void main()
{
#ifdef THICKNESS_PASS
  if (deposit != 0)
  {
    // Thickness pass, particle under 1.5 pixels: its share of the bilinear (cloud-in-cell)
    // deposit, dropped where the opaque scene is in front of its centre.
    vec2 weight = max(vec2(0.0), 1.0 - abs(gl_FragCoord.xy - depositCentre));
    vec4 clip = VCDCMatrix * vec4(centreVC, 1.0);
    float centreDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
    if (useOpaqueDepth != 0 && centreDepth >= texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy * opaqueDepthScale), 0).r)
    {
      discard;
    }
    gl_FragDepth = centreDepth;
    gl_FragData[0] = vec4(depositValue * weight.x * weight.y, 0.0, 0.0, 0.0);
    return;
  }
#endif
  // The ray through this pixel: from the quad's interpolated position, or for a point sprite
  // from the pixel itself.
#ifdef POINT_SPRITES
  vec2 ndc = gl_FragCoord.xy / targetSize * 2.0 - 1.0;
  vec3 through = parallelProjection != 0 ? vec3((ndc - projection.zw) / projection.xy, 0.0)
                                         : vec3((ndc + projection.zw) / projection.xy, -1.0);
#else
  vec3 through = quadVC;
#endif
  vec3 origin = vec3(0.0);
  vec3 dir = normalize(through);
  if (parallelProjection != 0)
  {
    origin = vec3(through.xy, centreVC.z + 2.0 * radiusVC);
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
#ifdef THICKNESS_PASS
  gl_FragData[0] = vec4(2.0 * h, 0.0, 0.0, 0.0);
#else
  gl_FragData[0] = vec4(-hit.z, 0.0, 0.0, 0.0);
  gl_FragData[1] = particleColor;
#endif
}
