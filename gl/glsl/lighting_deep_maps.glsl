// The deep shadow maps' lookup: the layers of a texel, the receiver's plane, the filter.

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
