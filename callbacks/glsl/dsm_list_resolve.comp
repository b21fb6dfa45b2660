// Resolves a deep shadow map face's fragment lists (after dsm_list_common.glsl) into the
// layers the peel passes of dsm_build.frag would have stored: each texel's nearest uLayers
// surfaces in the order (distance, triangle), each with its distance and the visibility after
// it, and, where the layers run out, the closing layer: the nearest opaque surface behind
// them, visibility 0 (callbacks/DeepShadowMap.h).
//
// It reports the face's flags: which layers hold a surface in some texel, down to which a
// surface behind lets light through, and whether a closing layer exists, from which the build
// counts the layers the peel would keep and sizes the map (MapFragmentLists). With
// IVSHADOW_MAP_LIST_STORE it also writes the uKept layers the map keeps, from array layer
// uFirstLayer on, in every texel ("no surface" where a texel has fewer), so the map needs
// neither scratch layers nor a clear: in the layout of the last build, which a light moved a
// little keeps (one run), or, when the flags say otherwise, again in the new one.
// IVSHADOW_MAP_LIST_LAYERS (a power of two, at least uLayers) sizes the sort;
// IVSHADOW_MAP_VISIBILITY_FORMAT is the visibility array's image format.
//
// With IVSHADOW_MAP_LIST_MERGE (SoDeepShadowLight::layerOverflow MERGE), a texel whose
// surfaces that let light through, in front of its nearest opaque one, are more than uLayers
// keeps them all, merged into uLayers groups (after Lokovic and Veach 2000: the stored depths
// a subset of the surfaces', the error in visibility bounded and reported) instead of the
// nearest uLayers. Texels with fewer are stored as without it, so the layout is the same.
layout(local_size_x = IVSHADOW_MAP_RESOLVE_GROUP_SIZE,
       local_size_y = IVSHADOW_MAP_RESOLVE_GROUP_SIZE) in;

layout(r32ui, binding = IVSHADOW_FRAGMENT_HEADS_UNIT) uniform readonly uimage2DArray uHeads;
#ifdef IVSHADOW_MAP_LIST_STORE
layout(r32f, binding = IVSHADOW_MAP_LAYER_DEPTH_UNIT) uniform writeonly image2DArray uDepth;
layout(IVSHADOW_MAP_VISIBILITY_FORMAT, binding = IVSHADOW_MAP_LAYER_VISIBILITY_UNIT)
uniform writeonly image2DArray uVisibility;
uniform int uFirstLayer;  // the face's first layer in the map
uniform int uKept;        // layers the map keeps for the face
#endif

uniform int uLayers;  // maxLayers
uniform int uSize;    // texels per side
uniform int uFace;

// Per face, IVSHADOW_MAP_FACE_FLAGS words: bit k of words 0 and 1, layer k holds a surface
// in some texel (k < 64); of words 2 and 3, one that lets light through; word 4, some texel
// has a closing layer; word 5, the largest error a merge left in a texel's visibility (the
// bits of a float >= 0, which order as the floats do); word 6, the texels merged.
layout(std430, binding = IVSHADOW_MAP_FLAGS_BINDING) buffer FaceFlags {
  uint faceFlags[];
};

const float kNoSurface = 3.40282347e+38;  // as the build clears empty layers

// The peel's order: by distance, and of surfaces at one distance the lower numbered first.
bool nearer(float depth, uint triangle, float otherDepth, uint otherTriangle) {
  return depth < otherDepth || (depth == otherDepth && triangle < otherTriangle);
}

#ifdef IVSHADOW_MAP_LIST_MERGE
// A merging texel's surfaces that let light through in front of its closing one: the nearest
// kMergeSurfaces sorted (their distance, triangle and transmittance), and the rest as one
// item that follows them, stored at the nearest one's distance (passing all of them; its own
// error is the nearest one's transmittance less all of theirs). Four times the layers, so
// that most texels keep every surface apart, up to 64 (the sort is per texel); always more
// than the layers.
const int kMergeSurfaces = max(min(4 * IVSHADOW_MAP_LIST_LAYERS, 64), IVSHADOW_MAP_LIST_LAYERS + 1);
float itemDepth[kMergeSurfaces + 1];
uint itemTriangle[kMergeSurfaces + 1];
vec3 itemPasses[kMergeSurfaces + 1];
vec3 restFirst = vec3(1.0);  // the rest's nearest surface's transmittance
bool rest = false;
int items = 0;
// The groups the items are stored as, nearest first: a group's first item's distance and
// the light left after the group.
float groupDepth[IVSHADOW_MAP_LIST_LAYERS];
vec3 groupAfter[IVSHADOW_MAP_LIST_LAYERS];

float largest(vec3 v) { return max(v.r, max(v.g, v.b)); }

// The light item i passes in front (its first surface's transmittance).
vec3 firstPasses(int i) { return i == kMergeSurfaces ? restFirst : itemPasses[i]; }

// Gathers the items: every surface that lets light through in front of the closing one (all
// of them where there is none), by insertion into the nearest kMergeSurfaces, the surfaces
// pushed out going into the rest.
void gatherItems(uint head, bool closing, float closingDepth, uint closingTriangle) {
  float restDepth = 0.0;
  uint restTriangle = 0u;
  vec3 restPasses = vec3(1.0);
  uint steps = 0u;
  for (uint i = head; i != kNoFragment && steps < capacity; i = fragments[i].next, ++steps) {
    if (fragments[i].transmittance.a != 0.0) continue;
    float depth = fragments[i].depth;
    uint triangle = fragments[i].triangle;
    if (closing && !nearer(depth, triangle, closingDepth, closingTriangle)) continue;
    vec3 passes = fragments[i].transmittance.rgb;
    if (items == kMergeSurfaces) {
      // Full: this surface, or the farthest kept one, goes into the rest.
      int last = kMergeSurfaces - 1;
      bool keep = nearer(depth, triangle, itemDepth[last], itemTriangle[last]);
      float outDepth = keep ? itemDepth[last] : depth;
      uint outTriangle = keep ? itemTriangle[last] : triangle;
      vec3 outPasses = keep ? itemPasses[last] : passes;
      restPasses *= outPasses;
      if (!rest || nearer(outDepth, outTriangle, restDepth, restTriangle)) {
        restDepth = outDepth;
        restTriangle = outTriangle;
        restFirst = outPasses;
      }
      rest = true;
      if (!keep) continue;
      --items;
    }
    int j = items++;
    while (j > 0 && nearer(depth, triangle, itemDepth[j - 1], itemTriangle[j - 1])) {
      itemDepth[j] = itemDepth[j - 1];
      itemTriangle[j] = itemTriangle[j - 1];
      itemPasses[j] = itemPasses[j - 1];
      --j;
    }
    itemDepth[j] = depth;
    itemTriangle[j] = triangle;
    itemPasses[j] = passes;
  }
  if (rest) {
    itemDepth[kMergeSurfaces] = restDepth;
    itemTriangle[kMergeSurfaces] = restTriangle;
    itemPasses[kMergeSurfaces] = restPasses;
  }
}

// The item at position i of the merge (the rest, when there is one, after the sorted ones).
int itemAt(int i) { return i < items ? i : kMergeSurfaces; }

// Groups the n items in order into uLayers groups, each as long as its error stays within
// `bound` but leaving an item for every group after it. A group from item i to j, with the
// light `before` reaching it, errs by before x (what item i passes - what all pass): within
// it the true light lies between the light after item i and the light after j, and the map
// stores the latter. Returns the largest error of a group, or, where the groups run out
// before the items (the bound is too low), a value above 1. With `keep`, sets the groups.
float groupItems(int n, float bound, bool keep) {
  vec3 before = vec3(1.0);
  float worst = 0.0;
  int i = 0;
  for (int g = 0; g < uLayers; ++g) {
    if (i == n) return 2.0;  // cannot happen with n > uLayers; guards the loop
    vec3 first = firstPasses(itemAt(i));
    vec3 all = itemPasses[itemAt(i)];
    int j = i;
    while (j + 1 <= n - (uLayers - g) &&
           largest(before * (first - all * itemPasses[itemAt(j + 1)])) <= bound) {
      ++j;
      all *= itemPasses[itemAt(j)];
    }
    if (g == uLayers - 1 && j != n - 1) return 2.0;
    worst = max(worst, largest(before * (first - all)));
    if (keep) {
      groupDepth[g] = itemDepth[itemAt(i)];
      groupAfter[g] = before * all;
    }
    before *= all;
    i = j + 1;
  }
  return worst;
}

// Lokovic and Veach bound the error and find the fewest vertices; here the layers are fixed,
// so the least bound that uLayers groups meet is searched for (by halving: a group's error
// only grows as it takes more items, so grouping greedily within a bound is the fewest groups
// for it), and the items grouped within it. Returns the error left.
float mergeItems() {
  int n = items + (rest ? 1 : 0);
  float low = 0.0, high = 1.0;
  for (int step = 0; step < 24; ++step) {
    float middle = 0.5 * (low + high);
    if (groupItems(n, middle, false) <= 1.0)
      high = middle;
    else
      low = middle;
  }
  return groupItems(n, high, true);
}
#endif

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, ivec2(uSize)))) return;
  float depths[IVSHADOW_MAP_LIST_LAYERS];
  uint triangles[IVSHADOW_MAP_LIST_LAYERS];
  uint indices[IVSHADOW_MAP_LIST_LAYERS];
  int count = 0;
  // The nearest opaque surface among those left out of the layers: every one left out lies
  // behind all that are kept. And whether one left out lets light through.
  bool closing = false;
  bool passingLeftOut = false;
  float closingDepth = 0.0;
  uint closingTriangle = 0u;
  float passingDepth = 0.0;  // the nearest left out that lets light through
  uint passingTriangle = 0u;
  // A list holds at most `capacity` fragments: the bound only guards the loop.
  uint steps = 0u;
  const uint head = imageLoad(uHeads, ivec3(texel, uFace)).r;
  for (uint i = head; i != kNoFragment && steps < capacity; i = fragments[i].next, ++steps) {
    float depth = fragments[i].depth;
    uint triangle = fragments[i].triangle;
    uint index = i;
    if (count == uLayers) {
      // Full: this fragment, or the farthest kept one, is left out.
      bool keep = nearer(depth, triangle, depths[count - 1], triangles[count - 1]);
      uint left = keep ? indices[count - 1] : index;
      float leftDepth = keep ? depths[count - 1] : depth;
      uint leftTriangle = keep ? triangles[count - 1] : triangle;
      if (fragments[left].transmittance.a == 0.0) {
        if (!passingLeftOut || nearer(leftDepth, leftTriangle, passingDepth, passingTriangle)) {
          passingDepth = leftDepth;
          passingTriangle = leftTriangle;
        }
        passingLeftOut = true;
      } else if (!closing || nearer(leftDepth, leftTriangle, closingDepth, closingTriangle)) {
        closing = true;
        closingDepth = leftDepth;
        closingTriangle = leftTriangle;
      }
      if (!keep) continue;
      --count;
    }
    int j = count++;
    while (j > 0 && nearer(depth, triangle, depths[j - 1], triangles[j - 1])) {
      depths[j] = depths[j - 1];
      triangles[j] = triangles[j - 1];
      indices[j] = indices[j - 1];
      --j;
    }
    depths[j] = depth;
    triangles[j] = triangle;
    indices[j] = index;
  }
  bool closed = count == uLayers && closing;
#ifdef IVSHADOW_MAP_LIST_MERGE
  // Merged where a surface that lets light through was left out in front of the closing one
  // and no kept one is opaque (past an opaque surface no light is left to get wrong).
  bool opaqueKept = false;
  for (int k = 0; k < count; ++k)
    opaqueKept = opaqueKept || fragments[indices[k]].transmittance.a != 0.0;
  bool merging = passingLeftOut && !opaqueKept &&
                 (!closing || nearer(passingDepth, passingTriangle, closingDepth, closingTriangle));
  if (merging) {
    gatherItems(head, closing, closingDepth, closingTriangle);
    float error = mergeItems();
    int flagWords = uFace * IVSHADOW_MAP_FACE_FLAGS;
    atomicMax(faceFlags[flagWords + 5], floatBitsToUint(error));
    atomicAdd(faceFlags[flagWords + 6], 1u);
  }
#endif
#ifdef IVSHADOW_MAP_LIST_STORE
  vec3 visibility = vec3(1.0);
  for (int k = 0; k < uKept; ++k) {
    float depth = kNoSurface;
    vec4 stored = vec4(1.0);
#ifdef IVSHADOW_MAP_LIST_MERGE
    if (merging && k < count) {
      depth = groupDepth[k];
      stored = vec4(groupAfter[k], 1.0);
    } else
#endif
    if (k < count) {
      visibility *= fragments[indices[k]].transmittance.rgb;
      depth = depths[k];
      stored = vec4(visibility, 1.0);
    } else if (k == uLayers && closed) {
      depth = closingDepth;
      stored = vec4(0.0, 0.0, 0.0, 1.0);
    }
    imageStore(uDepth, ivec3(texel, uFirstLayer + k), vec4(depth));
    imageStore(uVisibility, ivec3(texel, uFirstLayer + k), stored);
  }
#endif
  // Gathered here and set with one atomic each, not one per layer. The peel's pass k is told
  // that light is left when any surface behind layer k - 1 lets light through, whatever its
  // rank (dsm_build.frag raises the flag before the depth test picks the nearest): bit k of
  // passingLayers is set up to the deepest such surface, to the last layer when one was left
  // out.
  int deepestPassing = passingLeftOut ? uLayers - 1 : -1;
  for (int k = 0; k < count; ++k)
    if (fragments[indices[k]].transmittance.a == 0.0) deepestPassing = max(deepestPassing, k);
  uvec2 held = uvec2(0u), passing = uvec2(0u);
  for (int k = 0; k < count; ++k) held[k / 32] |= 1u << uint(k % 32);
  for (int k = 0; k <= deepestPassing; ++k) passing[k / 32] |= 1u << uint(k % 32);
  int flags = uFace * IVSHADOW_MAP_FACE_FLAGS;
  for (int w = 0; w < 2; ++w) {
    if (held[w] != 0u) atomicOr(faceFlags[flags + w], held[w]);
    if (passing[w] != 0u) atomicOr(faceFlags[flags + 2 + w], passing[w]);
  }
  if (closed) atomicOr(faceFlags[flags + 4], 1u);
}
