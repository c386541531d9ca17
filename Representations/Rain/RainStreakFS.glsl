//VTK::System::Dec
//VTK::Output::Dec
//=========================================================================
// ParaFluid rain: a streak's colour by precomputed radiance transfer. The drop's transfer vector
// for the view direction (lambda_l Y_lm(v): the geometric-optics phase function of a water drop
// convolved with the harmonics, a table computed once on the CPU) dotted with the environment's
// coefficients gives the radiance the drop sends to the eye; the scene behind shows through the
// streak's alpha profile (soft across, tapered at the ends by the motion blur of the exposure).
//=========================================================================
uniform sampler2D transfer;      // width x (4 * rows): 4 blocks of 4 coefficients
uniform int transferRows;
uniform vec3 environment[16];    // the environment's SH coefficients (RGB)
uniform float brightness;
uniform float opacity;
uniform float fogDistance;       // 0: no fog
uniform int radianceOnly;        // 1: opaque quads of the radiance (checking and tuning)

in vec2 streakCoord;
in vec2 capFraction;
flat in float coverage;
in vec3 viewDirection;
flat in float eyeDistance;

vec3 dropRadiance(vec3 v)
{
  v = normalize(v);
  int width = textureSize(transfer, 0).x;
  float azimuth = atan(v.y, v.x);
  azimuth = azimuth < 0.0 ? azimuth + 6.28318530718 : azimuth;
  int col = int(azimuth / 6.28318530718 * float(width)) % width;
  int row = clamp(int((v.z + 1.0) * 0.5 * float(transferRows)), 0, transferRows - 1);
  vec3 radiance = vec3(0.0);
  for (int block = 0; block < 4; ++block)
  {
    vec4 t = texelFetch(transfer, ivec2(col, block * transferRows + row), 0);
    radiance += t.x * environment[4 * block] + t.y * environment[4 * block + 1] +
                t.z * environment[4 * block + 2] + t.w * environment[4 * block + 3];
  }
  return max(radiance, vec3(0.0));
}

void main()
{
  vec3 color = brightness * dropRadiance(viewDirection);
  if (radianceOnly != 0)
  {
    gl_FragData[0] = vec4(color, 1.0);
    return;
  }
  float across = exp(-2.0 * streakCoord.y * streakCoord.y);
  // The ends fade over the caps: the drop enters and leaves the exposure.
  float x = streakCoord.x;
  float ends = smoothstep(0.0, 2.0 * capFraction.x, x) * smoothstep(0.0, 2.0 * capFraction.y, 1.0 - x);
  float fog = fogDistance > 0.0 ? exp(-eyeDistance / fogDistance) : 1.0;
  float alpha = clamp(opacity * coverage * across * ends * fog, 0.0, 1.0);
  if (alpha < 1.0 / 512.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(color, alpha);
}
