// Coin's lighting (the fixed-function equations Coin programs through glLight/glMaterial)
// evaluated per pixel, with each deep shadow light's contribution multiplied by the
// visibility looked up in its cube deep shadow map.
const int kMaxLights = 8;  // kMaxGlLights in callbacks/GlLimits.h

#ifdef IVSHADOW_PEEL_PASSES
// The peel passes' variant: the depth test against the opaque picture (less, no writes)
// runs before shading, so hidden and opaque fragments cost nothing. The other passes must
// not use it: there a discarded fragment must not write depth.
layout(early_fragment_tests) in;
#endif

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
uniform vec4 uMapParams[kMaxLights];  // resolution, unused, bias (texels), filter radius
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
  vec3 d = localPosition - uMapLight[slot];
  int face = cubeFace(d);
  float depth = dot(d, kFaceAxis[face]);
  if (depth <= 0.0) return vec3(1.0);
  vec2 ndc = vec2(dot(d, kFaceRight[face]), dot(d, kFaceUp[face])) / depth;
  int resolution = int(uMapParams[slot].x);
  // Bias in texels of this face at the receiver's depth, growing with the slope of the
  // receiver as seen from the light so grazing receivers do not shadow themselves.
  float texelSize = 2.0 * depth / float(resolution);
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

// The map of the GL light, found by its position: Coin numbers GL lights by traversal and
// reuses a number when a separator ends, so only the position says which light it is.
int mapOfLight(gl_LightSourceParameters light) {
  if (light.position.w == 0.0) return -1;
  vec3 at = light.position.xyz / light.position.w;
  for (int slot = 0; slot < uMapCount; ++slot)
    if (distance(at, uMapLightEye[slot]) <= 1e-3 * (1.0 + length(uMapLightEye[slot])))
      return slot;
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

// Depth peeling of SoPeelingSeparator (seeds/000 §2, Bavoil & Myers 2008). Targets: 0 the
// depth range still to peel (-near, far) under MAX blending, 1 the front layers blended
// "under" (rgb, 1 - transmittance), 2 this pass's back layer. Every fragment passes the
// previous values through, so MAX keeps them where no fragment of this pass changes them.
const int kPeelOff = 0;
const int kPeelOpaque = 1;       // the opaque pass: only fully opaque fragments
const int kPeelInit = 2;         // first pass: the depth range of transparent fragments
const int kPeelFrontToBack = 3;  // one layer per pass, nearest first
const int kPeelDual = 4;         // the nearest and the farthest layer per pass
const int kRayOpaque = 5;       // capture: the nearest opaque surface's position
const int kRayTransparent = 6;  // capture: the nearest transparent one behind the last
uniform int uPeelMode;
uniform sampler2D uPeelDepth;
uniform sampler2D uPeelFront;
layout(std430, binding = 1) buffer PeelProgress {
  uint deeperLayers;  // some fragment lies strictly inside the range still to peel
};

void peel(vec4 texel, float alpha) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float z = gl_FragCoord.z;
  // Opaque fragments were drawn in the opaque pass. Transparent ones behind them never get
  // here: the early depth test against the opaque depth (IVSHADOW_PEEL_PASSES) drops them.
  if (isOpaque(alpha)) discard;
  if (uPeelMode == kPeelInit) {
    gl_FragData[0] = vec4(-z, z, 0.0, 0.0);
    gl_FragData[1] = vec4(0.0);
    gl_FragData[2] = vec4(0.0);
    deeperLayers = 1u;
    return;
  }
  vec2 range = texelFetch(uPeelDepth, pixel, 0).xy;
  float near = -range.x;
  float far = uPeelMode == kPeelDual ? range.y : 2.0;
  vec4 front = texelFetch(uPeelFront, pixel, 0);
  gl_FragData[0] = vec4(-1.0, -1.0, 0.0, 0.0);
  gl_FragData[1] = front;
  gl_FragData[2] = vec4(0.0);
  // Coin may draw a shape differently from pass to pass (immediate mode, then a render
  // cache that splits its polygons differently), which moves depth by a few ulps: depths
  // that close count as the same layer.
  const float kSameLayer = 1e-6;
  if (z < near - kSameLayer || z > far + kSameLayer) return;  // peeled in an earlier pass
  bool onNear = abs(z - near) <= kSameLayer, onFar = abs(z - far) <= kSameLayer;
  if (!onNear && !onFar) {
    gl_FragData[0].xy = vec2(-z, uPeelMode == kPeelDual ? z : -1.0);
    deeperLayers = 1u;
    return;
  }
  vec4 colour = shade(texel);
  if (onNear) {
    float transmittance = 1.0 - front.a;
    gl_FragData[1] = vec4(front.rgb + colour.rgb * colour.a * transmittance,
                          1.0 - transmittance * (1.0 - colour.a));
  } else {
    gl_FragData[2] = colour;
  }
}

// Capture passes for RAYS lights: attachment 0 gets the surface's position in the group's
// coordinates and its window depth, attachment 1 its geometric normal and 2.0 in alpha (a
// shape Coin draws without this program writes a colour, alpha <= 1, and is not traced).
uniform sampler2D uRayOpaque;    // the opaque capture (alpha: window depth)
uniform sampler2D uRayPrevious;  // the previous transparent capture
uniform int uRayFirstTransparent;

void capture(float alpha) {
  // Derivatives first: after a discard they are undefined.
  vec3 local = (uEyeToLocal * vec4(vEyePosition, 1.0)).xyz;
  vec3 normal = cross(dFdx(local), dFdy(local));
  if (alpha <= 0.0) discard;
  float z = gl_FragCoord.z;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  const float kSameLayer = 1e-6;
  if (uPeelMode == kRayOpaque) {
    if (!isOpaque(alpha)) discard;
  } else {
    if (isOpaque(alpha)) discard;
    if (z >= texelFetch(uRayOpaque, pixel, 0).a - kSameLayer) discard;
    if (uRayFirstTransparent == 0 && z <= texelFetch(uRayPrevious, pixel, 0).a + kSameLayer)
      discard;
  }
  gl_FragData[0] = vec4(local, z);
  gl_FragData[1] = vec4(normal, 2.0);
}

void main() {
  vec4 texel = coin_texunit0_model != kTextureNone ? texture(textureMap0, gl_TexCoord[0].st)
                                                   : vec4(1.0);
  if (uPeelMode == kRayOpaque || uPeelMode == kRayTransparent) {
    capture(applyTextureModel(gl_Color, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb).a);
    return;
  }
  if (uPeelMode >= kPeelInit) {
    // The opacity alone decides what a peel pass does; most fragments need no shading.
    float alpha =
        applyTextureModel(gl_Color, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb).a;
    peel(texel, alpha);
    return;
  }
  vec4 colour = shade(texel);
  if (uPeelMode == kPeelOpaque && !isOpaque(colour.a)) discard;
  gl_FragData[0] = colour;
}
