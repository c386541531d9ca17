//VTK::System::Dec
//VTK::Output::Dec
//=========================================================================
// ParaFluid rain splashes: the sprite's water coverage, lit by the environment's mean radiance.
//=========================================================================
uniform sampler2D atlas;
uniform vec3 ambient;
uniform float brightness;
uniform float opacity;

in vec2 atlasCoord;
flat in float fade;

void main()
{
  float coverage = texture(atlas, atlasCoord).a;
  float alpha = clamp(opacity * coverage * fade, 0.0, 1.0);
  if (alpha < 1.0 / 256.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(brightness * ambient, alpha);
}
