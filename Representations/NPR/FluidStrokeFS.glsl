//=========================================================================
// ParaFluid brush strokes: a procedural bristle brush. The stroke narrows over its last fifths;
// it is split across into `bristles` bands, each with its own shade and its own ragged start and
// end, so a stroke reads as paint. Strokes are kept to the fluid's footprint on screen (where the
// smoothed fluid depth is set) and to the visible surface: a stroke more than hideDepth behind
// the surface is discarded. The fragment takes the surface's window depth, so the opaque scene
// in front of the fluid still hides it (depth test LEQUAL, no depth writes).
//=========================================================================
uniform ivec2 viewportOrigin; // the viewport's first pixel in the framebuffer
uniform mat4 VCDCMatrix;
uniform float hideDepth;      // world units
uniform float bristles;

in float along;
in float across;
in float eyeDistance;
flat in vec3 strokeColor;
flat in float strokeSeed;

//VTK::Output::Dec

float hash(float x)
{
  return fract(sin(x * 12.9898) * 43758.5453);
}

void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy) - viewportOrigin;
  float d = fetchDepth(p);
  if (d <= 0.0 || eyeDistance > d + hideDepth)
  {
    discard;
  }
  float taper = sqrt(clamp(min(along, 1.0 - along) / 0.2, 0.0, 1.0));
  if (abs(across) > mix(0.3, 1.0, taper))
  {
    discard;
  }
  float bristle = floor((0.5 * across + 0.5) * bristles);
  float shade = hash(bristle + 17.0 * strokeSeed);
  float ragged = hash(3.1 * bristle + 5.0 * strokeSeed + 1.0);
  if (along < 0.12 * shade || along > 1.0 - 0.12 * ragged)
  {
    discard;
  }
  gl_FragData[0] = vec4(strokeColor * (0.8 + 0.35 * shade), 1.0);
  vec4 clip = VCDCMatrix * vec4(eyePosition(vec2(p) + 0.5, d), 1.0);
  // A hair nearer than the shading pass wrote for the same surface, so LEQUAL passes.
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5 - 1e-6, 0.0, 1.0);
}
