// Merges the surfaces of the texels dsm_list_resolve.comp queued (after dsm_list_common.glsl):
// those whose surfaces that let light through, in front of the nearest opaque one, are more
// than uLayers (SoDeepShadowLight::layerOverflow MERGE). After Lokovic and Veach (2000), each
// such texel keeps all of them, in uLayers groups of neighbours, each stored at its first
// surface's distance with the light left after all of its surfaces; the resolve has stored
// the nearest uLayers and the closing layer, and this pass writes the uLayers over them. A
// point behind them all gets its light exactly; one within a group, at most the group's
// error, of which the largest is reported. IVSHADOW_MAP_LIST_LAYERS (a power of two, at least
// uLayers) sizes the arrays; IVSHADOW_MAP_VISIBILITY_FORMAT is the visibility array's format.
layout(local_size_x = IVSHADOW_MAP_MERGE_GROUP_SIZE) in;

layout(r32ui, binding = IVSHADOW_FRAGMENT_HEADS_UNIT) uniform readonly uimage2DArray uHeads;
layout(r32f, binding = IVSHADOW_MAP_LAYER_DEPTH_UNIT) uniform writeonly image2DArray uDepth;
layout(IVSHADOW_MAP_VISIBILITY_FORMAT, binding = IVSHADOW_MAP_LAYER_VISIBILITY_UNIT)
uniform writeonly image2DArray uVisibility;

uniform int uLayers;        // maxLayers
uniform int uFaceFirst[6];  // each face's first layer in the map

// dsm_list_resolve.comp's flags; this pass sets word 5 of each face, the largest error a
// merge left in a texel's visibility (the bits of a float >= 0, which order as floats do).
layout(std430, binding = IVSHADOW_MAP_FLAGS_BINDING) buffer FaceFlags {
  uint faceFlags[];
};

// A merging texel's surfaces that let light through in front of its closing one: the nearest
// kMergeSurfaces sorted (their distance, triangle and transmittance), and the rest as one
// item that follows them, stored at the nearest one's distance (passing all of them; its own
// error is the nearest one's transmittance less all of theirs). Four times the sort's size
// (maxLayers rounded up to a power of two), so that most texels keep every surface apart, up
// to 64 (the sort is per texel); always more than the layers.
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

// The error of a group that the light `before` reaches, whose surfaces at its first distance
// pass `first` and all of which pass `all`. `precise`: the bisection and the grouping it
// settles on must compute the same value, or a bound found to hold could fail.
float groupError(vec3 before, vec3 first, vec3 all) {
  precise vec3 wrong = before * (first - all);
  return largest(wrong);
}

// Groups the n items in order into uLayers groups, each as long as its error stays within
// `bound` but leaving an item for every group after it. A group from item i to j, with the
// light `before` reaching it, errs by before x (what its surfaces at item i's distance pass -
// what all pass): within it the true light lies between the light after those and the light
// after j, and the map stores the latter. Surfaces at one distance have no point between
// them, so merging them costs nothing. Returns the largest error of a group, or, where the
// groups run out before the items (the bound is too low), a value above 1. With `keep`, sets
// the groups.
float groupItems(int n, float bound, bool keep) {
  vec3 before = vec3(1.0);
  float worst = 0.0;
  int i = 0;
  for (int g = 0; g < uLayers; ++g) {
    if (i == n) return 2.0;  // cannot happen with n > uLayers; guards the loop
    vec3 first = firstPasses(itemAt(i));
    vec3 all = itemPasses[itemAt(i)];
    int j = i;
    while (j + 1 <= n - (uLayers - g)) {
      vec3 next = itemPasses[itemAt(j + 1)];
      // (Not the rest: only its nearest surface lies at its distance.)
      bool tied = itemAt(j + 1) != kMergeSurfaces && itemDepth[itemAt(j + 1)] == itemDepth[itemAt(i)];
      if (!tied && groupError(before, first, all * next) > bound) break;
      ++j;
      all *= next;
      if (tied) first *= next;
    }
    if (g == uLayers - 1 && j != n - 1) return 2.0;
    worst = max(worst, groupError(before, first, all));
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
  float error = groupItems(n, high, true);
  // A bound of 1 always holds (no error exceeds the light there is): should rounding have
  // failed the one found, the groups are still all set.
  return error <= 1.0 ? error : groupItems(n, 1.0, true);
}

// Merges the texel queued at `index`.
void mergeTexel(uint index) {
  uint word = mergeTexels[index];
  int face = int(word >> 28);
  ivec2 texel = ivec2(int(word & 0x3fffu), int((word >> 14) & 0x3fffu));
  const uint head = imageLoad(uHeads, ivec3(texel, face)).r;
  // The closing surface: the nearest opaque one (the resolve found none among the nearest
  // uLayers, so it is the one it closed the texel with).
  bool closing = false;
  float closingDepth = 0.0;
  uint closingTriangle = 0u;
  uint steps = 0u;
  for (uint i = head; i != kNoFragment && steps < capacity; i = fragments[i].next, ++steps) {
    if (fragments[i].transmittance.a == 0.0) continue;
    if (!closing ||
        nearer(fragments[i].depth, fragments[i].triangle, closingDepth, closingTriangle)) {
      closing = true;
      closingDepth = fragments[i].depth;
      closingTriangle = fragments[i].triangle;
    }
  }
  items = 0;
  rest = false;
  restFirst = vec3(1.0);
  gatherItems(head, closing, closingDepth, closingTriangle);
  float error = mergeItems();
  for (int g = 0; g < uLayers; ++g) {
    imageStore(uDepth, ivec3(texel, uFaceFirst[face] + g), vec4(groupDepth[g]));
    imageStore(uVisibility, ivec3(texel, uFaceFirst[face] + g), vec4(groupAfter[g], 1.0));
  }
  atomicMax(faceFlags[face * IVSHADOW_MAP_FACE_FLAGS + 5], floatBitsToUint(error));
}

void main() {
  uint stride = gl_NumWorkGroups.x * uint(IVSHADOW_MAP_MERGE_GROUP_SIZE);
  for (uint index = gl_GlobalInvocationID.x; index < mergeCount; index += stride)
    mergeTexel(index);
}
