// Per-pixel fragment lists (an A-buffer; Yang, Hensley, Grün and Thibieroz 2010), shared by
// the pass that fills them (fragment_list.frag) and the one that resolves them
// (fragment_list_resolve.frag). Each pixel's head (an image) names its latest fragment;
// each fragment names the one before. Sizes and bindings: callbacks/ShaderConstants.h.
const uint kNoFragment = 0xffffffffu;

struct ListFragment {
  vec4 colour;  // shaded, straight alpha
  float depth;  // window depth
  uint next;    // the pixel's previous fragment, or kNoFragment
};

layout(std430, binding = IVSHADOW_FRAGMENT_LIST_BINDING) coherent buffer FragmentList {
  uint used;      // fragments the pass tried to store: past `capacity`, it is redone larger
  uint capacity;  // fragments the buffer holds
  uint crowded;   // a pixel had more than IVSHADOW_MAX_FRAGMENTS_PER_PIXEL: peel instead
  uint unused;
  ListFragment fragments[];
};
