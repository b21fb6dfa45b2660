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
// resolution, 1 for a directional light (uMapLight*: the direction towards it), bias (texels),
// filter width (texels; 0: the nearest texel)
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
// An opacity map's sliced distances (near, far) and slices per face; z = 0: a deep shadow map.
uniform vec3 uMapSlices[kMaxLights];
// Lights with method RAYS keep no map: their visibility was traced on the CPU per pixel and
// per captured surface layer (callbacks/RayShadowPass.h).
uniform int uMapRay[kMaxLights];  // index among the traced lights, -1 for a map
uniform sampler2DArray uRayDepth;       // window depth of each captured layer (1: none)
uniform sampler2DArray uRayVisibility;  // layer ray * uRayLayers + captured layer
uniform int uRayLayers;  // the ray textures are indexed by window coordinates

// Each part below is compiled in only where the frame needs it (IVSHADOW_WITH_*: why, in
// nodes/ShadingProgram.h's ShadingFeatures).
#ifdef IVSHADOW_WITH_RAYS
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
#endif

#ifdef IVSHADOW_WITH_OPACITY_MAPS
// An opacity map (callbacks/OpacityMap.h): none of the light past the nearest opaque surface;
// before it, exp(-sum) of each slice's absorption weighted by how far the receiver lies past
// the slice's first surface, in slices, up to 1 (seeds/002's min((d - alpha) N, 1)). Only the
// receiver's slice and the one before can count in part: a slice two or more before it ends
// a whole slice before the receiver, and one after it begins behind. Slice k holds the
// absorption through its far end, so the part before those two is read from one slice.
float sliceWeight(float s, float first, float slices) {
  return clamp((s - first) * slices, 0.0, 1.0);
}

vec3 opacityVisibility(int slot, ivec2 texel, int face, float depth) {
  vec3 range = uMapSlices[slot];
  int slices = int(range.z);
  if (slices == 0) return vec3(1.0);  // the map failed to build: no shadow
  if (texelFetch(uMapDepth[slot], ivec3(texel, face), 0).r < depth) return vec3(0.0);
  float s = (depth - range.x) / (range.y - range.x);
  int k = clamp(int(floor(s * range.z)), 0, slices - 1);
  int layer = face * slices + k;
  vec4 here = texelFetch(uMapVisibility[slot], ivec3(texel, layer), 0);
  vec4 before = k >= 1 ? texelFetch(uMapVisibility[slot], ivec3(texel, layer - 1), 0)
                       : vec4(0.0, 0.0, 0.0, IVSHADOW_OPACITY_EMPTY_SLICE);
  vec3 earlier = k >= 2 ? texelFetch(uMapVisibility[slot], ivec3(texel, layer - 2), 0).rgb
                        : vec3(0.0);
  vec3 absorbed = earlier + (before.rgb - earlier) * sliceWeight(s, before.a, range.z) +
                  (here.rgb - before.rgb) * sliceWeight(s, here.a, range.z);
  return exp(-(uMapColoured[slot] != 0 ? absorbed : absorbed.rrr));
}
#endif

#ifdef IVSHADOW_WITH_MAPS
vec3 visibilityAt(int slot, ivec2 texel, int face, float depth) {
#ifdef IVSHADOW_WITH_OPACITY_MAPS
#ifdef IVSHADOW_WITH_DEEP_MAPS
  if (uMapSlices[slot].z > 0.0)
#endif
    return opacityVisibility(slot, texel, face, depth);
#endif
#ifdef IVSHADOW_WITH_DEEP_MAPS
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
#endif
}
#endif

// The receiver's geometric normal in the group's coordinates, the plane of its triangle (the
// shading normal may bend away from it). beginShading() computes it in uniform control flow:
// derivatives are undefined in branches that not every fragment of a quad takes, and the peel
// passes shade only some fragments.
vec3 gFaceNormal = vec3(0.0);
void beginShading() {
#ifdef IVSHADOW_WITH_MAPS
  vec3 p = (uEyeToLocal * vec4(vEyePosition, 1.0)).xyz;
  vec3 n = cross(dFdx(p), dFdy(p));
  float length2 = dot(n, n);
  gFaceNormal = length2 > 0.0 ? n * inversesqrt(length2) : vec3(0.0);
#endif
}

#ifdef IVSHADOW_WITH_MAPS

// The map's view of the group's coordinates: (x w, y w, depth, w), ndc = xy / w, depth
// as the build stores it (dsm_build.frag): a one-face map's lookup matrix, or a cube face's.
mat4 mapMatrix(int slot, int face) {
  if (uMapProjection[slot] != IVSHADOW_MAP_CUBE) return uMapLookup[slot];
  vec3 light = uMapLight[slot];
  vec3 right = kFaceRight[face], up = kFaceUp[face], axis = kFaceAxis[face];
  vec4 depthRow = vec4(axis, -dot(axis, light));
  return transpose(mat4(vec4(right, -dot(right, light)), vec4(up, -dot(up, light)), depthRow,
                        depthRow));
}

// The depth of the receiver's plane on the ray through a texel's centre (ndc), which is the
// ray the build sampled that texel on: comparing the stored surfaces with the plane there,
// rather than with the point, a planar receiver never shadows itself and needs no slope-scaled
// bias (receiver plane depth, after Isidoro 2006). `mapped`, `e1`, `e2`: the point and two
// directions along its plane in the map's coordinates. A plane that contains the ray, or is
// nearly so, is taken at the point's own depth; the plane is trusted at most `reach` away.
float planeDepthAt(vec2 ndc, vec4 mapped, vec4 e1, vec4 e2, float reach) {
  float a11 = e1.x - ndc.x * e1.w, a12 = e2.x - ndc.x * e2.w;
  float a21 = e1.y - ndc.y * e1.w, a22 = e2.y - ndc.y * e2.w;
  float b1 = ndc.x * mapped.w - mapped.x, b2 = ndc.y * mapped.w - mapped.y;
  float det = a11 * a22 - a12 * a21;
  float scale = (abs(a11) + abs(a12)) * (abs(a21) + abs(a22));
  if (!(abs(det) > 1e-6 * scale)) return mapped.z;
  float a = (b1 * a22 - a12 * b2) / det, b = (a11 * b2 - a21 * b1) / det;
  return clamp(mapped.z + a * e1.z + b * e2.z, mapped.z - reach, mapped.z + reach);
}

vec3 deepShadowVisibility(int slot, vec3 localPosition) {
  int face = 0;
  if (uMapProjection[slot] == IVSHADOW_MAP_CUBE) {
    vec3 d = localPosition - uMapLight[slot];
    face = cubeFace(d);
    if (dot(d, kFaceAxis[face]) <= 0.0) return vec3(1.0);
  }
  mat4 toMap = mapMatrix(slot, face);
  vec4 mapped = toMap * vec4(localPosition, 1.0);
  // Behind a spot light, or beside a one-face map: no caster of the map lies between the point
  // and the light (a spot light's cone ends inside its face).
  if (mapped.w <= 0.0) return vec3(1.0);
  vec2 ndc = mapped.xy / mapped.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return vec3(1.0);
  float depth = mapped.z;
  float resolution = uMapParams[slot].x;
  float width = uMapParams[slot].w;
  // A texel's width at the receiver's depth; the bias is in those.
  float texel = (uMapTexelScale[slot].x * max(depth, 0.0) + uMapTexelScale[slot].y) / resolution;
  float bias = uMapParams[slot].z * texel;
  vec3 n = gFaceNormal;
  vec3 along = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t1 = normalize(cross(n, along));
  vec4 e1 = toMap * vec4(t1, 0.0), e2 = toMap * vec4(cross(n, t1), 0.0);
  bool plane = dot(n, n) > 0.0;
  // The plane is followed at most ten times the taps' distance: a receiver that steep to the
  // light (84 degrees) is lit by a tenth of the light or less.
  float reach = 10.0 * (1.0 + width) * texel;
  vec2 at = (ndc * 0.5 + 0.5) * resolution;
  int last = int(resolution) - 1;
#ifdef IVSHADOW_WITH_NEAREST_TEXEL
#ifdef IVSHADOW_WITH_FILTERED_MAPS
  if (width <= 0.0)
#endif
  {
    ivec2 centre = clamp(ivec2(floor(at)), ivec2(0), ivec2(last));
    vec2 centreNdc = (vec2(centre) + 0.5) / resolution * 2.0 - 1.0;
    float receiver = plane ? planeDepthAt(centreNdc, mapped, e1, e2, reach) : depth;
    return visibilityAt(slot, centre, face, receiver - bias);
  }
#endif
#ifdef IVSHADOW_WITH_FILTERED_MAPS
  // PCF: the mean of the map's nearest-texel visibility over a width x width square centred
  // on the point, each texel weighted by its overlap with the square (width 1: bilinear).
  vec2 low = at - 0.5 * width, high = at + 0.5 * width;
  ivec2 first = ivec2(floor(low)), end = ivec2(ceil(high));
  vec3 sum = vec3(0.0);
  for (int y = first.y; y < end.y; ++y) {
    float wy = min(high.y, float(y + 1)) - max(low.y, float(y));
    for (int x = first.x; x < end.x; ++x) {
      float wx = min(high.x, float(x + 1)) - max(low.x, float(x));
      ivec2 tap = clamp(ivec2(x, y), ivec2(0), ivec2(last));
      vec2 tapNdc = (vec2(tap) + 0.5) / resolution * 2.0 - 1.0;
      float receiver = plane ? planeDepthAt(tapNdc, mapped, e1, e2, reach) : depth;
      sum += (wx * wy) * visibilityAt(slot, tap, face, receiver - bias);
    }
  }
  return sum / (width * width);
#endif
}
#endif

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

#ifdef IVSHADOW_WITH_BOUNCE
// One diffuse bounce (SoTransparentShadowGroup::bounce): the virtual point lights
// (raytrace/BounceLights.h; position, normal, flux per light in uBounceLights) that see the
// receiver in their imperfect shadow maps (callbacks/ImperfectShadowMaps.h), summed as
// (1 / pi) flux cos_x cos_i / (r^2 + a^2), each light a disc of radius a (BounceLight), in
// the group's coordinates.
uniform samplerBuffer uBounceLights;
uniform sampler2D uBounceAtlas;
uniform int uBounceCount;
uniform int uBounceTiles;
uniform int uBounceMapSize;
uniform float uBounceLift;
uniform mat3 uEyeToLocalNormal;

vec3 bouncedLight(vec3 x, vec3 n) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < uBounceCount; ++i) {
    int first = IVSHADOW_BOUNCE_TEXELS_PER_LIGHT * i;
    vec3 y = texelFetch(uBounceLights, first).xyz;
    vec3 ny = texelFetch(uBounceLights, first + 1).xyz;
    vec3 towards = y - x;
    float squared = dot(towards, towards);
    if (!(squared > 0.0)) continue;
    vec3 w = towards * inversesqrt(squared);
    float receiving = dot(n, w);
    float sending = -dot(ny, w);
    if (receiving <= 0.0 || sending <= 0.0) continue;
    // The receiver as the light's map sees it: its direction and distance from the lifted
    // light, hidden when a surface lies nearer that way. It is first moved off its surface
    // towards the light by kIsmNormalOffset texels of the map at its distance (normal-offset
    // shadow mapping), so that the splats of its own surface around it, seen at a slant, lie
    // behind it rather than in front.
    float reach = sqrt(squared);
    vec3 moved = x + n * (IVSHADOW_ISM_NORMAL_OFFSET / float(uBounceMapSize) * reach);
    vec3 d = moved - (y + uBounceLift * ny);
    float distance = length(d);
    vec3 l = bounceLocal(ny, d / distance);
    if (l.z <= 0.0) continue;
    ivec2 texel = bounceTile(i, uBounceTiles, uBounceMapSize) +
                  clamp(ivec2(bounceTexel(l, uBounceMapSize)), ivec2(0), ivec2(uBounceMapSize - 1));
    float stored = texelFetch(uBounceAtlas, texel, 0).r;
    if (distance > stored * (1.0 + IVSHADOW_ISM_BIAS)) continue;
    vec4 flux = texelFetch(uBounceLights, first + 2);  // w: the disc's radius squared
    sum += flux.rgb * (receiving * sending / (squared + flux.w));
  }
  return sum * IVSHADOW_INVERSE_PI;
}
#endif

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

