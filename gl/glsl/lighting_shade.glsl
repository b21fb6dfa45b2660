// shade(): the lights summed, then the texture model and the fog, as Coin's fixed function.

vec4 shade(vec4 texel) {
  vec4 colour = gl_Color;
  if (coin_light_model != 0) {
    vec3 normal = normalize(vEyeNormal);
    if (coin_two_sided_lighting != 0 && !gl_FrontFacing) normal = -normal;
    vec3 localPosition = (uEyeToLocal * vec4(vEyePosition, 1.0)).xyz;
    vec3 lit = gl_FrontMaterial.emission.rgb +
               gl_LightModel.ambient.rgb * gl_FrontMaterial.ambient.rgb;
    for (int i = 0; i < uLightCount; ++i)
      lit += lightContribution(i, normal, localPosition, gl_Color.rgb);
#ifdef IVSHADOW_WITH_BOUNCE
    lit += gl_Color.rgb * bouncedLight(localPosition, normalize(uEyeToLocalNormal * normal));
#endif
    colour = vec4(clamp(lit, 0.0, 1.0), gl_Color.a);
  }
  if (coin_texunit0_model != kTextureNone)
    colour = applyTextureModel(colour, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb);
#ifdef IVSHADOW_WITH_FOG
  if (uFogType != 0) {
    float z = gl_FogFragCoord;
    float fog = uFogType == 1   ? (gl_Fog.end - z) * gl_Fog.scale
                : uFogType == 2 ? exp(-gl_Fog.density * z)
                                : exp(-gl_Fog.density * gl_Fog.density * z * z);
    colour.rgb = mix(gl_Fog.color.rgb, colour.rgb, clamp(fog, 0.0, 1.0));
  }
#endif
  return colour;
}
