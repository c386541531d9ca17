//VTK::System::Dec
//=========================================================================
// ParaFluid rain: each drop a streak across the view, built from gl_VertexID (one triangle a
// drop): the segment the drop travelled during the exposure (from position - velocity /
// |velocity| * streak_length to position), widened on screen to the drop's projected diameter
// (at least one pixel; a thinner drop covers the pixel in proportion) and capped at both ends by
// half a width. The triangle encloses that capsule (twice its area; the fragment shader discards
// the rest): under a software rasteriser (llvmpipe) the cost of a streak is its triangles' setup,
// and one triangle with few interpolated values sets up in well under half the time of a quad.
// The drop's colour is computed here, once per vertex, and passed flat: across a streak a few
// pixels long the view direction does not change. It is one read of the drop's radiance toward
// the eye, tabulated per view direction for the environment on the CPU.
//=========================================================================
uniform samplerBuffer drops; // per drop: (x, y, z, diameter), (vx, vy, vz, streak_length)
uniform mat4 WCVCMatrix;
uniform mat4 VCDCMatrix;
uniform vec2 viewport;       // pixels
uniform float widthScale;    // streak width over the drop's diameter
uniform float maxStreakArea; // the most pixels a streak may cover (StreakRaster.h's limit: all of
                             // them together cover at most 16 views, whatever widthScale is)
uniform vec3 eye;            // camera position, world
uniform float brightness;
uniform float opacity;
uniform float fogDistance;   // 0: no fog

// The drop's radiance toward each view direction (2 x rows azimuths by rows heights): its
// transfer vector (lambda_l Y_lm(v): the geometric-optics phase function of a water drop
// convolved with the harmonics) dotted with the environment's coefficients, on the CPU once per
// environment.
uniform sampler2D radiance;

vec3 dropRadiance(vec3 v)
{
  v = normalize(v);
  ivec2 size = textureSize(radiance, 0);
  float azimuth = atan(v.y, v.x);
  azimuth = azimuth < 0.0 ? azimuth + 6.28318530718 : azimuth;
  int col = int(azimuth / 6.28318530718 * float(size.x)) % size.x;
  int row = clamp(int((v.z + 1.0) * 0.5 * float(size.y)), 0, size.y - 1);
  return texelFetch(radiance, ivec2(col, row), 0).rgb;
}

out vec2 streakCoord;        // x: along (0 at the tail's cap, 1 at the head's), y: across (-1..1)
flat out float capFraction;  // each cap's share of streakCoord.x
flat out vec4 dropColour;    // the radiance sent to the eye; a: coverage x fog x opacity

void main()
{
  int drop = gl_VertexID / 3;
  int corner = gl_VertexID - 3 * drop;
  vec4 a = texelFetch(drops, 2 * drop);
  vec4 b = texelFetch(drops, 2 * drop + 1);
  vec3 head = a.xyz;
  float speed = length(b.xyz);
  vec3 along = speed > 0.0 ? b.xyz / speed : vec3(0.0, 0.0, -1.0);
  vec3 tail = head - along * b.w;
  vec4 headVC = WCVCMatrix * vec4(head, 1.0);
  vec4 tailVC = WCVCMatrix * vec4(tail, 1.0);
  streakCoord = vec2(0.0);
  capFraction = 0.0;
  dropColour = vec4(0.0);
  // A streak partly behind the eye is cut at 1 mm in front of it; wholly behind: a degenerate
  // triangle inside the view (one outside it would send the draw through the clipper).
  float nearZ = -1e-3;
  if (headVC.z > nearZ && tailVC.z > nearZ)
  {
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  if (headVC.z > nearZ)
  {
    headVC = mix(tailVC, headVC, (tailVC.z - nearZ) / (tailVC.z - headVC.z));
  }
  if (tailVC.z > nearZ)
  {
    tailVC = mix(headVC, tailVC, (headVC.z - nearZ) / (headVC.z - tailVC.z));
  }
  vec4 headDC = VCDCMatrix * headVC;
  vec4 tailDC = VCDCMatrix * tailVC;
  float headDepth = headDC.z / headDC.w;
  if (headDepth > 1.0)
  {
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // beyond the far plane
    return;
  }
  vec2 headPx = headDC.xy / headDC.w * 0.5 * viewport;
  vec2 tailPx = tailDC.xy / tailDC.w * 0.5 * viewport;
  vec2 direction = headPx - tailPx;
  float lengthPx = length(direction);
  direction = lengthPx > 1e-3 ? direction / lengthPx : vec2(0.0, 1.0);
  vec2 normal = vec2(-direction.y, direction.x);
  // Projected diameter at the drop (perspective: P11 * D / depth * half the viewport height).
  float depth = max(-headVC.z, 1e-3);
  float diameterPx = widthScale * a.w * VCDCMatrix[1][1] / depth * 0.5 * viewport.y;
  float halfWidth = min(0.5 * max(diameterPx, 1.0),
                        max(0.25 * (sqrt(lengthPx * lengthPx + 4.0 * maxStreakArea) - lengthPx), 0.5));
  float total = lengthPx + 2.0 * halfWidth;
  // Off screen (the capsule's box outside the viewport) or fainter than a level of an 8-bit
  // channel: a degenerate triangle, which the rasteriser drops before any setup.
  float fog = fogDistance > 0.0 ? exp(-length(head - eye) / fogDistance) : 1.0;
  float peakAlpha = opacity * min(diameterPx, 1.0) * fog;
  vec2 low = min(headPx, tailPx) - halfWidth, high = max(headPx, tailPx) + halfWidth;
  if (any(greaterThan(low, 0.5 * viewport)) || any(lessThan(high, -0.5 * viewport)) || peakAlpha < 1.0 / 512.0)
  {
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  // The capsule is u in [0, total] along from the tail cap's start, v in [-1, 1] half-widths
  // across; the triangle (0, -2), (0, 2), (2 total, 0) holds it.
  float u = corner == 2 ? 2.0 * total : 0.0;
  float v = corner == 0 ? -2.0 : (corner == 1 ? 2.0 : 0.0);
  vec2 px = tailPx - direction * halfWidth + direction * u + normal * (v * halfWidth);
  // Drawn at the head's depth: a streak is a few pixels long, and w = 1 keeps the interpolation
  // linear on screen.
  gl_Position = vec4(px / (0.5 * viewport), max(headDepth, -1.0), 1.0);
  streakCoord = vec2(u / total, v);
  capFraction = halfWidth / total;
  dropColour = vec4(brightness * dropRadiance(head - eye), peakAlpha);
}
