// Coin's lighting (the fixed-function equations Coin programs through glLight/glMaterial)
// evaluated per pixel, with each deep shadow light's contribution multiplied by the
// visibility looked up in its deep shadow map (a cube, or one face): shade(), shared by the camera pass
// (shading.frag) and the peel passes (peel.frag), which put their main() after it.
const int kMaxLights = IVSHADOW_MAX_LIGHTS;

in vec3 vEyePosition;
in vec3 vEyeNormal;

// Kept up to date by Coin (SoShaderObject's coin_* parameters).
uniform int coin_light_model;
uniform int coin_two_sided_lighting;
uniform int coin_texunit0_model;
uniform sampler2D textureMap0;

uniform int uLightCount;
uniform mat4 uEyeToLocal;
uniform int uFogType;  // SoEnvironmentElement::FogType

uniform sampler2DArray uMapDepth[kMaxLights];
uniform sampler2DArray uMapVisibility[kMaxLights];
uniform int uMapCount;
uniform vec3 uMapLight[kMaxLights];     // light position in the group's coordinates
uniform vec3 uMapLightEye[kMaxLights];  // ... and in eye coordinates
// resolution, 1 for a directional light (uMapLight*: its direction), bias (texels), filter radius
uniform vec4 uMapParams[kMaxLights];
// How each map sees its casters (IVSHADOW_MAP_*, callbacks/MapFrame.h); for a one-face map the
// group's coordinates to (x w, y w, depth, w); a texel's size at depth d, times the
// resolution: uMapTexelScale.x * d + uMapTexelScale.y.
uniform int uMapProjection[kMaxLights];
uniform mat4 uMapLookup[kMaxLights];
uniform vec2 uMapTexelScale[kMaxLights];
uniform int uMapColoured[kMaxLights];
uniform int uMapFaceFirst[kMaxLights * 6];   // array layer of each face's first layer
uniform int uMapFaceLayers[kMaxLights * 6];  // layers stored for each face
// Lights with method RAYS keep no map: their visibility was traced on the CPU per pixel and
// per captured surface layer (callbacks/RayShadowPass.h).
uniform int uMapRay[kMaxLights];  // index among the traced lights, -1 for a map
uniform sampler2DArray uRayDepth;       // window depth of each captured layer (1: none)
uniform sampler2DArray uRayVisibility;  // layer ray * uRayLayers + captured layer
uniform int uRayLayers;  // the ray textures are indexed by window coordinates

// The traced visibility of the captured surface this fragment is (same depth). A fragment
// deeper than every captured transparent layer takes the layer nearest in depth.
vec3 rayVisibility(int ray) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float z = gl_FragCoord.z;
  int best = -1;
  float bestDistance = 2.0;
  for (int layer = 0; layer < uRayLayers; ++layer) {
    float captured = texelFetch(uRayDepth, ivec3(pixel, layer), 0).r;
    if (captured >= 1.0) continue;
    float distance = abs(captured - z);
    if (distance < bestDistance) {
      best = layer;
      bestDistance = distance;
    }
    // The surface itself (Coin may move a redrawn shape's depth by a few ulps): no need to
    // look at deeper layers.
    if (distance <= 1e-6) break;
  }
  if (best < 0) return vec3(1.0);
  return texelFetch(uRayVisibility, ivec3(pixel, ray * uRayLayers + best), 0).rgb;
}

vec3 visibilityAt(int slot, ivec2 texel, int face, float depth) {
  vec3 visibility = vec3(1.0);
  int first = uMapFaceFirst[slot * 6 + face];
  int layers = uMapFaceLayers[slot * 6 + face];
  for (int k = 0; k < layers; ++k) {
    int layer = first + k;
    // Layers are sorted by depth; a texel with fewer surfaces holds +huge beyond the last.
    if (texelFetch(uMapDepth[slot], ivec3(texel, layer), 0).r >= depth) break;
    vec4 stored = texelFetch(uMapVisibility[slot], ivec3(texel, layer), 0);
    visibility = uMapColoured[slot] != 0 ? stored.rgb : stored.rrr;
  }
  return visibility;
}

vec3 deepShadowVisibility(int slot, vec3 localPosition, float cosTheta) {
  int face = 0;
  float depth;
  vec2 ndc;
  if (uMapProjection[slot] == IVSHADOW_MAP_CUBE) {
    vec3 d = localPosition - uMapLight[slot];
    face = cubeFace(d);
    depth = dot(d, kFaceAxis[face]);
    if (depth <= 0.0) return vec3(1.0);
    ndc = vec2(dot(d, kFaceRight[face]), dot(d, kFaceUp[face])) / depth;
  } else {
    vec4 mapped = uMapLookup[slot] * vec4(localPosition, 1.0);
    // Behind a spot light, or beside the face: no caster of the map lies between the point
    // and the light (a spot light's cone ends inside its face).
    if (mapped.w <= 0.0) return vec3(1.0);
    ndc = mapped.xy / mapped.w;
    if (any(greaterThan(abs(ndc), vec2(1.0)))) return vec3(1.0);
    depth = mapped.z;
  }
  int resolution = int(uMapParams[slot].x);
  // Bias in texels of this face at the receiver's depth, growing with the slope of the
  // receiver as seen from the light so grazing receivers do not shadow themselves.
  float texelSize = (uMapTexelScale[slot].x * max(depth, 0.0) + uMapTexelScale[slot].y) /
                    float(resolution);
  float c = clamp(cosTheta, 1e-3, 1.0);
  float tanTheta = sqrt(max(1.0 - c * c, 0.0)) / c;
  float receiver = depth - uMapParams[slot].z * texelSize * (1.0 + min(tanTheta, 10.0));

  ivec2 centre = clamp(ivec2(floor((ndc * 0.5 + 0.5) * float(resolution))), ivec2(0),
                       ivec2(resolution - 1));
  int radius = int(uMapParams[slot].w);
  vec3 sum = vec3(0.0);
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      ivec2 texel = clamp(centre + ivec2(dx, dy), ivec2(0), ivec2(resolution - 1));
      sum += visibilityAt(slot, texel, face, receiver);
    }
  float taps = float((2 * radius + 1) * (2 * radius + 1));
  return sum / taps;
}

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

vec3 lightContribution(int i, vec3 normal, vec3 localPosition, vec3 diffuseColour) {
  gl_LightSourceParameters light = gl_LightSource[i];
  vec3 toLight;
  float attenuation = 1.0;
  if (light.position.w == 0.0) {
    toLight = normalize(light.position.xyz);
  } else {
    vec3 v = light.position.xyz / light.position.w - vEyePosition;
    float distance = length(v);
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
    int slot = mapOfLight(light);
    if (slot >= 0)
      direct *= uMapRay[slot] >= 0 ? rayVisibility(uMapRay[slot])
                                   : deepShadowVisibility(slot, localPosition, nDotL);
    colour += direct;
  }
  return attenuation * colour;
}

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
    colour = vec4(clamp(lit, 0.0, 1.0), gl_Color.a);
  }
  if (coin_texunit0_model != kTextureNone)
    colour = applyTextureModel(colour, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb);
  if (uFogType != 0) {
    float z = gl_FogFragCoord;
    float fog = uFogType == 1   ? (gl_Fog.end - z) * gl_Fog.scale
                : uFogType == 2 ? exp(-gl_Fog.density * z)
                                : exp(-gl_Fog.density * gl_Fog.density * z * z);
    colour.rgb = mix(gl_Fog.color.rgb, colour.rgb, clamp(fog, 0.0, 1.0));
  }
  return colour;
}

