// Per-pixel fragment lists (an A-buffer; Yang, Hensley, Grün and Thibieroz 2010), shared by
// the pass that fills them (fragment_list.frag) and the one that resolves them
// (fragment_list_resolve.frag). A pixel's first `fixedLayers` fragments go into slots of its
// own, fragment k of pixel p at k * pixels + p, numbered by the pixel's count (an image); the
// rest are linked into an overflow list after them, each pixel's head (an image) naming its
// latest and each fragment the one before. Sizes and bindings: gl/ShaderConstants.h.
const uint kNoFragment = 0xffffffffu;

struct ListFragment {
  uvec2 colour;  // shaded, straight alpha: four 16-bit unorms (packUnorm2x16)
  float depth;   // window depth
  uint next;     // in the overflow list: the pixel's previous overflow fragment, or kNoFragment
};

// Not coherent: the resolve reads what the list pass wrote after a barrier, and the counters
// are changed by atomics only, so the header's sizes may be cached.
layout(std430, binding = IVSHADOW_FRAGMENT_LIST_BINDING) buffer FragmentList {
  uint fixedLayers;       // slots of its own per pixel
  uint width;             // pixels per row of the images, which window coordinates index
  uint pixels;            // of the images
  uint crowded;           // a pixel had more than IVSHADOW_MAX_FRAGMENTS_PER_PIXEL: peel instead
  uint overflowUsed;      // overflow fragments the pass tried to store: past the capacity, it
                          // is redone larger
  uint overflowCapacity;  // overflow fragments the buffer holds
  uint unused0;
  uint unused1;
  ListFragment fragments[];
};

uvec2 packColour(vec4 colour) {
  return uvec2(packUnorm2x16(colour.rg), packUnorm2x16(colour.ba));
}

vec4 unpackColour(uvec2 bits) {
  return vec4(unpackUnorm2x16(bits.x), unpackUnorm2x16(bits.y));
}
