// Coin's light equation (GL's fixed-function lighting, evaluated per point) in the one text
// that both languages compile, as scene/surface_optics.glsl: the GLSL programs have it embedded
// after that file (gl/GlProgram.cpp's composeShader) and gl/glsl/
// lighting_lights.glsl calls it in eye space; raytrace/LightEquation.cpp includes it with glm
// and the CPU scene tracer calls it in world space. It keeps to what both read alike (see
// surface_optics.glsl) and leaves the shadow out: GLSL multiplies it in, the tracer asks a
// shadow ray later.

// Where a light is seen from `position`: xyz the unit direction towards it, w GL's distance
// and spot attenuation of its light there. `light` is GL's homogeneous light position (w = 0:
// a directional light, xyz towards it); `falloff` GL's constant, linear and quadratic
// attenuation; `spot` whether it is a spot light (GL's cutoff not 180).
vec4 lightIncidence(vec4 light, vec3 position, vec3 falloff, bool spot, vec3 spotDirection,
                    float spotCosCutoff, float spotExponent) {
  if (light.w == 0.0f) return vec4(normalize(vec3(light)), 1.0f);
  vec3 v = vec3(light) / light.w - position;
  float distance = length(v);
  // Past float's range (a light about 2e19 away) the distance is infinite and the light
  // reaches nothing, as in Coin's fixed-function GL; 0 x inf in the attenuation would make
  // the whole pixel NaN (black).
  if (isinf(distance)) return vec4(0.0f);
  vec3 toLight = distance > 0.0f ? v / distance : vec3(0.0f, 0.0f, 1.0f);
  float attenuation =
      1.0f / (falloff.x + falloff.y * distance + falloff.z * distance * distance);
  if (spot) {
    float spotCos = dot(-toLight, normalize(spotDirection));
    attenuation *= spotCos < spotCosCutoff ? 0.0f : pow(spotCos, spotExponent);
  }
  return vec4(toLight, attenuation);
}

// The light a surface of unit normal `normal` sends towards the eye from a light in unit
// direction `toLight`, before the attenuation and the shadow: Lambert's diffuse and
// Blinn-Phong's specular of GL, none where the light is behind the surface. Coin leaves GL's
// non-local viewer, so `towardsEye` is one direction for the whole picture (eye space's +z).
vec3 directLight(vec3 normal, vec3 toLight, vec3 towardsEye, vec3 diffuse, vec3 lightDiffuse,
                 vec3 specular, vec3 lightSpecular, float shininess) {
  float nDotL = dot(normal, toLight);
  if (!(nDotL > 0.0f)) return vec3(0.0f);
  vec3 halfVector = normalize(toLight + towardsEye);
  float nDotH = max(dot(normal, halfVector), 0.0f);
  vec3 direct = nDotL * lightDiffuse * diffuse;
  if (nDotH > 0.0f) direct += pow(nDotH, shininess) * lightSpecular * specular;
  return direct;
}
