// A deep shadow map's fragment lists (MapFragmentLists), shared by the pass that fills them
// (dsm_list.frag) and the one that resolves them into layers (dsm_list_resolve.comp). Each
// texel's head (in a layer per face of an image array) names its latest fragment; each
// fragment names the one before. Sizes and bindings: callbacks/ShaderConstants.h.
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
