// The opacity maps' lookup.

#ifdef IVSHADOW_WITH_OPACITY_MAPS
// An opacity map (gl/OpacityMap.h): none of the light past the nearest opaque surface;
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
