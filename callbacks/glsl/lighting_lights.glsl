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

vec3 lightContribution(int i, vec3 normal, vec3 localPosition, vec3 diffuseColour) {
  gl_LightSourceParameters light = gl_LightSource[i];
  vec3 toLight;
  float attenuation = 1.0;
  if (light.position.w == 0.0) {
    toLight = normalize(light.position.xyz);
  } else {
    vec3 v = light.position.xyz / light.position.w - vEyePosition;
    float distance = length(v);
    // Past float's range (a light about 2e19 away) the distance is infinite and the light
    // reaches nothing, as in Coin's fixed-function GL and the tracer; 0 x inf in the
    // attenuation would make the whole pixel NaN (black).
    if (isinf(distance)) return vec3(0.0);
    toLight = v / distance;
    attenuation = 1.0 / (light.constantAttenuation + light.linearAttenuation * distance +
                         light.quadraticAttenuation * distance * distance);
    if (light.spotCutoff <= 90.0) {
      float spotCos = dot(-toLight, normalize(light.spotDirection));
      attenuation *= spotCos < light.spotCosCutoff ? 0.0 : pow(spotCos, light.spotExponent);
    }
  }
  float nDotL = dot(normal, toLight);
  vec3 colour = light.ambient.rgb * gl_FrontMaterial.ambient.rgb;
  if (nDotL > 0.0) {
    // Coin leaves GL's non-local viewer: the eye direction is +z in eye space.
    vec3 halfVector = normalize(toLight + vec3(0.0, 0.0, 1.0));
    float nDotH = max(dot(normal, halfVector), 0.0);
    vec3 direct = nDotL * light.diffuse.rgb * diffuseColour;
    if (nDotH > 0.0)
      direct += pow(nDotH, gl_FrontMaterial.shininess) * light.specular.rgb *
                gl_FrontMaterial.specular.rgb;
#if defined(IVSHADOW_WITH_MAPS) || defined(IVSHADOW_WITH_RAYS)
    int slot = mapOfLight(light);
    if (slot >= 0) direct *= shadowVisibility(slot, localPosition);
#endif
    colour += direct;
  }
  return attenuation * colour;
}
