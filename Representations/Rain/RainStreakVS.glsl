//VTK::System::Dec
//=========================================================================
// ParaFluid rain: each drop a streak across the view, built from gl_VertexID (six vertices a drop):
// the segment the drop travelled during the exposure (from position - velocity / |velocity| *
// streak_length to position), widened on screen to the drop's projected diameter (at least one
// pixel; a thinner drop covers the pixel in proportion) and capped at both ends by half a width.
//=========================================================================
uniform samplerBuffer drops; // per drop: (x, y, z, diameter), (vx, vy, vz, streak_length)
uniform mat4 WCVCMatrix;
uniform mat4 VCDCMatrix;
uniform vec2 viewport;       // pixels
uniform float widthScale;    // streak width over the drop's diameter
uniform vec3 eye;            // camera position, world

out vec2 streakCoord;        // x: along (0 at the tail, 1 at the drop), y: across (-1..1)
out vec2 capFraction;        // the cap's share of each end in streakCoord.x
flat out float coverage;     // fraction of a pixel the drop's width covers (<= 1)
out vec3 viewDirection;      // from the eye towards the drop, world
flat out float eyeDistance;

void main()
{
  int drop = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * drop;
  vec4 a = texelFetch(drops, 2 * drop);
  vec4 b = texelFetch(drops, 2 * drop + 1);
  vec3 head = a.xyz;
  float speed = length(b.xyz);
  vec3 along = speed > 0.0 ? b.xyz / speed : vec3(0.0, 0.0, -1.0);
  vec3 tail = head - along * b.w;
  vec4 headVC = WCVCMatrix * vec4(head, 1.0);
  vec4 tailVC = WCVCMatrix * vec4(tail, 1.0);
  // A streak partly behind the eye is cut at 1 mm in front of it; wholly behind: clipped.
  float nearZ = -1e-3;
  if (headVC.z > nearZ && tailVC.z > nearZ)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
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
  vec2 headPx = headDC.xy / headDC.w * 0.5 * viewport;
  vec2 tailPx = tailDC.xy / tailDC.w * 0.5 * viewport;
  vec2 direction = headPx - tailPx;
  float lengthPx = length(direction);
  direction = lengthPx > 1e-3 ? direction / lengthPx : vec2(0.0, 1.0);
  vec2 normal = vec2(-direction.y, direction.x);
  // Projected diameter at the drop (perspective: P11 * D / depth * half the viewport height).
  float depth = max(-headVC.z, 1e-3);
  float diameterPx = widthScale * a.w * VCDCMatrix[1][1] / depth * 0.5 * viewport.y;
  float widthPx = max(diameterPx, 1.0);
  coverage = min(diameterPx, 1.0);
  float halfWidth = 0.5 * widthPx;
  bool atHead = corner == 1 || corner == 2 || corner == 4;
  float side = (corner == 2 || corner == 4 || corner == 5) ? 1.0 : -1.0;
  vec4 endDC = atHead ? headDC : tailDC;
  vec2 offsetPx = normal * side * halfWidth + direction * (atHead ? halfWidth : -halfWidth);
  gl_Position = endDC + vec4(offsetPx / (0.5 * viewport) * endDC.w, 0.0, 0.0);
  float total = lengthPx + 2.0 * halfWidth;
  capFraction = vec2(halfWidth / total);
  streakCoord = vec2(atHead ? 1.0 : 0.0, side);
  viewDirection = head - eye;
  eyeDistance = length(head - eye);
}
