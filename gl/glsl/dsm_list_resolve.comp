// Resolves a deep shadow map face's fragment lists (after dsm_list_common.glsl) into the
// layers the peel passes of dsm_build.frag would have stored: each texel's nearest uLayers
// surfaces in the order (distance, triangle), each with its distance and the visibility after
// it, and, where the layers run out, the closing layer: the nearest opaque surface behind
// them, visibility 0 (gl/DeepShadowMap.h).
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
// With IVSHADOW_MAP_LIST_MERGE (SoDeepShadowLight::layerOverflow MERGE) it counts the texels
// whose surfaces that let light through, in front of the nearest opaque one, are more than
// uLayers, and, storing, queues them for dsm_list_merge.comp, which stores them merged over
// the nearest uLayers written here. The layout is the same either way.
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
// has a closing layer; word 5, the largest error a merge left in a texel's visibility
// (dsm_list_merge.comp); word 6, the texels to merge.
layout(std430, binding = IVSHADOW_MAP_FLAGS_BINDING) buffer FaceFlags {
  uint faceFlags[];
};

const float kNoSurface = 3.40282347e+38;  // as the build clears empty layers

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
    atomicAdd(faceFlags[uFace * IVSHADOW_MAP_FACE_FLAGS + 6], 1u);
#ifdef IVSHADOW_MAP_LIST_STORE
    uint queued = atomicAdd(mergeCount, 1u);
    atomicMax(mergeGroups, min(queued / uint(IVSHADOW_MAP_MERGE_GROUP_SIZE) + 1u, kMaxMergeGroups));
    mergeTexels[queued] = packMergeTexel(uFace, texel);
#endif
  }
#endif
#ifdef IVSHADOW_MAP_LIST_STORE
  vec3 visibility = vec3(1.0);
  for (int k = 0; k < uKept; ++k) {
    float depth = kNoSurface;
    vec4 stored = vec4(1.0);
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
