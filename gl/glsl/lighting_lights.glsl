// Coin's light equation per GL light, and which map shadows which light.

#if defined(IVSHADOW_WITH_MAPS) || defined(IVSHADOW_WITH_RAYS)
// The slot of the GL light, found by its position (a directional light's: its direction):
// Coin numbers GL lights by traversal and reuses a number when a separator ends, so only the
// position says which light it is.
int mapOfLight(gl_LightSourceParameters light) {
  bool directional = light.position.w == 0.0;
  vec3 at = directional ? normalize(light.position.xyz) : light.position.xyz / light.position.w;
  for (int slot = 0; slot < uMapCount; ++slot) {
    if ((uMapParams[slot].y != 0.0) != directional) continue;
    if (distance(at, uMapLightEye[slot]) <= 1e-3 * (1.0 + length(uMapLightEye[slot])))
      return slot;
  }
  return -1;
}

// The visibility of the light in `slot` from this fragment.
vec3 shadowVisibility(int slot, vec3 localPosition) {
#if defined(IVSHADOW_WITH_MAPS) && defined(IVSHADOW_WITH_RAYS)
  return uMapRay[slot] >= 0 ? rayVisibility(uMapRay[slot])
                            : deepShadowVisibility(slot, localPosition);
#elif defined(IVSHADOW_WITH_RAYS)
  return rayVisibility(uMapRay[slot]);
#else
  return deepShadowVisibility(slot, localPosition);
#endif
}
#endif

// Coin's light equation (scene/light_equation.glsl, which the CPU scene tracer compiles too) in
// eye space, with the light's shadow.
vec3 lightContribution(int i, vec3 normal, vec3 localPosition, vec3 diffuseColour) {
  gl_LightSourceParameters light = gl_LightSource[i];
  vec4 incidence = lightIncidence(
      light.position, vEyePosition,
      vec3(light.constantAttenuation, light.linearAttenuation, light.quadraticAttenuation),
      light.spotCutoff <= 90.0, light.spotDirection, light.spotCosCutoff, light.spotExponent);
  // Coin leaves GL's non-local viewer: the eye direction is +z in eye space.
  vec3 direct = directLight(normal, incidence.xyz, vec3(0.0, 0.0, 1.0), diffuseColour,
                            light.diffuse.rgb, gl_FrontMaterial.specular.rgb, light.specular.rgb,
                            gl_FrontMaterial.shininess);
#if defined(IVSHADOW_WITH_MAPS) || defined(IVSHADOW_WITH_RAYS)
  // Only light that reaches the surface asks for its shadow.
  if (direct != vec3(0.0)) {
    int slot = mapOfLight(light);
    if (slot >= 0) direct *= shadowVisibility(slot, localPosition);
  }
#endif
  return incidence.w * (light.ambient.rgb * gl_FrontMaterial.ambient.rgb + direct);
}
