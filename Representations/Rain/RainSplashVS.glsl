//VTK::System::Dec
//=========================================================================
// ParaFluid rain splashes: each impact a sprite standing on the surface (six vertices from
// gl_VertexID): its up axis the surface normal leaned by the impact angle, its side axis facing
// the camera, mirrored so that the sprite's downhill side (+x) points downhill. The frame of the
// sequence follows the impact's age; past the lifetime the splash is gone.
//=========================================================================
uniform samplerBuffer splashes; // per splash: (x, y, z, age), (nx, ny, nz, sequence + impact angle / 180)
uniform mat4 WCVCMatrix;
uniform mat4 VCDCMatrix;
uniform vec3 eye;
uniform float splashSize;   // [m]
uniform float lifetime;     // [s]

out vec2 atlasCoord;
flat out float fade;

void main()
{
  int splash = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * splash;
  vec4 a = texelFetch(splashes, 2 * splash);
  vec4 b = texelFetch(splashes, 2 * splash + 1);
  float age = a.w;
  if (!(age >= 0.0 && age < lifetime))
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  float sequence = floor(b.w);
  float impactAngle = radians(180.0 * fract(b.w));
  vec3 normal = normalize(b.xyz);
  vec3 downhill = vec3(normal.xy, 0.0);
  downhill = length(downhill) > 1e-4 ? normalize(downhill) : vec3(0.0);
  vec3 up = normalize(normal + 0.5 * tan(min(impactAngle, 1.3)) * downhill);
  vec3 toEye = eye - a.xyz;
  vec3 side = cross(up, toEye);
  side = length(side) > 1e-6 ? normalize(side) : vec3(1.0, 0.0, 0.0);
  if (dot(side, downhill) < 0.0)
  {
    side = -side;
  }
  float x = (corner == 1 || corner == 2 || corner == 4) ? 1.0 : 0.0;
  float y = (corner == 2 || corner == 4 || corner == 5) ? 1.0 : 0.0;
  vec3 world = a.xyz + splashSize * ((x - 0.5) * side + y * up);
  gl_Position = VCDCMatrix * (WCVCMatrix * vec4(world, 1.0));
  float frame = min(floor(age / lifetime * 6.0), 5.0);
  atlasCoord = vec2((frame + x) / 6.0, (sequence + y) / 3.0);
  fade = 1.0 - 0.5 * age / lifetime;
}
