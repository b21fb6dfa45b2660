// A deep shadow map's fragment lists (MapFragmentLists), shared by the pass that fills them
// (dsm_list.frag) and the one that resolves them into layers (dsm_list_resolve.comp). Each
// texel's head (in a layer per face of an image array) names its latest fragment; each
// fragment names the one before. Sizes and bindings: gl/ShaderConstants.h.
const uint kNoFragment = 0xffffffffu;

struct MapFragment {
  vec4 transmittance;  // rgb: the light that passes the surface; a: 1 where it is opaque
  float depth;         // the distance the map stores (dsm_build.frag)
  uint triangle;       // the triangle's number among all the casters': the order of ties
  uint next;           // the texel's previous fragment, or kNoFragment
};

layout(std430, binding = IVSHADOW_FRAGMENT_LIST_BINDING) coherent buffer MapFragmentList {
  uint used;      // fragments the faces tried to store: past `capacity`, redone larger
  uint capacity;  // fragments the buffer holds
  uint unused0;
  uint unused1;
  MapFragment fragments[];
};

// The peel's order: by distance, and of surfaces at one distance the lower numbered first.
bool nearer(float depth, uint triangle, float otherDepth, uint otherTriangle) {
  return depth < otherDepth || (depth == otherDepth && triangle < otherTriangle);
}

// The texels whose surfaces are merged (dsm_list_merge.comp), queued by the resolve: the
// merge runs one invocation per queued texel, not per texel of the face, since on a software
// rasteriser code that some invocations of a group skip costs all of them. The first three
// words are the merge's indirect dispatch (its groups, 1, 1).
layout(std430, binding = IVSHADOW_MAP_MERGE_QUEUE_BINDING) coherent buffer MapMergeQueue {
  uint mergeGroups;
  uint mergeGroupsY;
  uint mergeGroupsZ;
  uint mergeCount;
  uint mergeTexels[];
};

// The merge's groups at most: the least GL_MAX_COMPUTE_WORK_GROUP_COUNT GL guarantees. Past
// that many texels an invocation merges more than one.
const uint kMaxMergeGroups = 65535u;

// A face (below 8) and a texel (below 2^14 each way) in one word.
uint packMergeTexel(int face, ivec2 texel) {
  return (uint(face) << 28) | (uint(texel.y) << 14) | uint(texel.x);
}
