//VTK::System::Dec
//VTK::Output::Dec
//=========================================================================
// ParaFluid rain: a streak's alpha profile. The colour comes from the vertex shader (precomputed
// radiance transfer, one value a drop); the scene behind shows through the streak's profile: soft
// across, tapered at the ends by the motion blur of the exposure. The triangle is twice the
// streak: what lies outside the capsule is discarded.
//=========================================================================
uniform int radianceOnly; // 1: opaque streaks of the radiance (checking and tuning)

in vec2 streakCoord;
flat in float capFraction;
flat in vec4 dropColour;

void main()
{
  float x = streakCoord.x;
  if (x > 1.0 || abs(streakCoord.y) > 1.0)
  {
    discard;
  }
  if (radianceOnly != 0)
  {
    gl_FragData[0] = vec4(dropColour.rgb, 1.0);
    return;
  }
  float across = exp(-2.0 * streakCoord.y * streakCoord.y);
  // The ends fade over the caps: the drop enters and leaves the exposure.
  float ends = smoothstep(0.0, 2.0 * capFraction, x) * smoothstep(0.0, 2.0 * capFraction, 1.0 - x);
  float alpha = clamp(dropColour.a * across * ends, 0.0, 1.0);
  if (alpha < 1.0 / 512.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(dropColour.rgb, alpha);
}
