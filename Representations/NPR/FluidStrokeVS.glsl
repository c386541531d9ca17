//VTK::System::Dec
//=========================================================================
// ParaFluid brush strokes: each stroke segment as a screen-facing quad of constant width in
// pixels, built from gl_VertexID (six vertices per segment, no vertex arrays). A segment's quad
// reaches half a width past both its ends, so successive segments of a stroke overlap at the
// bends instead of leaving notches. Segments come from a texture buffer, three texels each:
// (start xyz, its stroke fraction), (end xyz, its stroke fraction), (stroke colour rgb, seed).
//=========================================================================
uniform samplerBuffer strokes;
uniform mat4 MCVCMatrix;
uniform mat4 VCDCMatrix;
uniform vec2 viewportSize; // pixels
uniform float halfWidth;   // pixels

out vec2 texCoord; // declared for the shared screen-pass code; the fragment shader uses gl_FragCoord
out float along;   // 0 at the stroke's start, 1 at its end (beyond at the caps)
out float across;  // -1 .. 1 across the stroke
out float eyeDistance;
flat out vec3 strokeColor;
flat out float strokeSeed;

void main()
{
  int segment = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * segment;
  // Two triangles: (start, -1) (end, -1) (end, +1) and (start, -1) (end, +1) (start, +1).
  bool atEnd = corner == 1 || corner == 2 || corner == 4;
  float side = (corner == 2 || corner == 4 || corner == 5) ? 1.0 : -1.0;
  vec4 a = texelFetch(strokes, 3 * segment);
  vec4 b = texelFetch(strokes, 3 * segment + 1);
  vec4 attributes = texelFetch(strokes, 3 * segment + 2);
  vec4 eyeA = MCVCMatrix * vec4(a.xyz, 1.0);
  vec4 eyeB = MCVCMatrix * vec4(b.xyz, 1.0);
  vec4 clipA = VCDCMatrix * eyeA;
  vec4 clipB = VCDCMatrix * eyeB;
  if (clipA.w <= 0.0 || clipB.w <= 0.0)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // behind the eye: clipped
    return;
  }
  vec2 screenA = clipA.xy / clipA.w * 0.5 * viewportSize;
  vec2 screenB = clipB.xy / clipB.w * 0.5 * viewportSize;
  vec2 direction = screenB - screenA;
  float pixels = length(direction);
  direction = pixels > 1e-4 ? direction / pixels : vec2(1.0, 0.0);
  vec2 normal = vec2(-direction.y, direction.x);
  vec2 screen = (atEnd ? screenB + halfWidth * direction : screenA - halfWidth * direction) + side * halfWidth * normal;
  vec4 clip = atEnd ? clipB : clipA;
  gl_Position = vec4(screen / (0.5 * viewportSize) * clip.w, clip.z, clip.w);
  float cap = (b.w - a.w) * halfWidth / max(pixels, 1e-4);
  along = atEnd ? b.w + cap : a.w - cap;
  across = side;
  eyeDistance = -(atEnd ? eyeB.z : eyeA.z);
  texCoord = screen / viewportSize + 0.5;
  strokeColor = attributes.rgb;
  strokeSeed = attributes.w;
}
