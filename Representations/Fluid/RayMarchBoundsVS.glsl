//VTK::System::Dec
//=========================================================================
// ParaFluid ray-marched fluid, start/stop depth from splats (after Xiao et al. 2017). Every point
// where phi reaches the iso value lies within the kernel's radius of a particle near the surface
// (DensityCellGrid's splat classes), so within the box of that particle's grid cell grown by the
// kernel's radius. Each such cell is splatted as the screen box of its grown box, on a coarse
// target (one pixel per `boundsPixel` viewport pixels) and grown by half a coarse pixel plus a
// margin, so every coarse pixel whose march rays can meet the box is covered; each fragment
// carries the box's nearest and farthest view depth (the fragment shader keeps their minimum and
// maximum per pixel, splash and bulk apart). A cell instead of each of its particles: several
// times fewer splats, each a little looser. Built from gl_VertexID: six vertices per cell, the
// whole screen for a box that reaches the near plane.
//=========================================================================
uniform samplerBuffer splatCells; // lower corner x, y, z [model], splat class (1: splash)
uniform mat4 MCVCMatrix;
uniform mat4 VCDCMatrix;
uniform float cellSize;     // [model units]
uniform float kernelRadius; // [model units]
uniform float nearDistance; // the camera's near clipping distance [view units]
uniform vec2 viewportSize;  // pixels
uniform vec2 boundsSize;    // pixels of the coarse target
uniform float boundsPixel;  // viewport pixels per coarse pixel
uniform int separateSplash; // 0: every cell into the bulk's pair

flat out vec2 depthSpan; // nearest, farthest view depth of the grown box
flat out float splash;

void main()
{
  int cell = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * cell;
  vec4 c = texelFetch(splatCells, cell);
  splash = (separateSplash != 0 && c.w > 0.5) ? 1.0 : 0.0;
  vec3 lo = c.xyz - kernelRadius;
  vec3 size = vec3(cellSize + 2.0 * kernelRadius);
  float near = 1e30, far = -1e30;
  vec2 ndcLo = vec2(1e30), ndcHi = vec2(-1e30);
  for (int k = 0; k < 8; ++k)
  {
    vec3 x = lo + size * vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
    vec4 e = MCVCMatrix * vec4(x, 1.0);
    float depth = -e.z / e.w;
    near = min(near, depth);
    far = max(far, depth);
    vec4 clip = VCDCMatrix * vec4(e.xyz / e.w, 1.0);
    vec2 ndc = clip.xy / clip.w;
    ndcLo = min(ndcLo, ndc);
    ndcHi = max(ndcHi, ndc);
  }
  depthSpan = vec2(max(near, 0.0), far);
  if (far < nearDistance)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // behind the near plane: clipped
    return;
  }
  if (near <= 0.5 * nearDistance)
  {
    ndcLo = vec2(-1.0); // reaches the eye's plane: its projection is unbounded
    ndcHi = vec2(1.0);
  }
  // Into coarse pixels, grown by half a pixel (a coarse pixel holds the rays within half a pixel
  // of its centre) and a safety margin; clamped to just past the target.
  float grow = 0.55;
  vec2 loPx = clamp((0.5 * ndcLo + 0.5) * viewportSize / boundsPixel - grow, vec2(-1.0), boundsSize + 1.0);
  vec2 hiPx = clamp((0.5 * ndcHi + 0.5) * viewportSize / boundsPixel + grow, vec2(-1.0), boundsSize + 1.0);
  vec2 k = vec2((corner == 1 || corner == 2 || corner == 4) ? 1.0 : 0.0,
                (corner == 2 || corner == 4 || corner == 5) ? 1.0 : 0.0);
  gl_Position = vec4(mix(loPx, hiPx, k) / boundsSize * 2.0 - 1.0, 0.0, 1.0);
}
