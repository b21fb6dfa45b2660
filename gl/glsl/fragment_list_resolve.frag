// Resolves the fragment lists (after fragment_list_common.glsl): each pixel's fragments, its
// own slots then its overflow list, are sorted by depth and composited front to back
// (seeds/000 eq. 2.5), written as the front layers' (rgb, transmittance) that the blend puts
// over the opaque picture: dst = src.rgb + dst * src.a (eq. 2.8), as the peel composite does.
layout(r32ui, binding = IVSHADOW_FRAGMENT_HEADS_UNIT) uniform readonly uimage2D uHeads;
layout(r32ui, binding = IVSHADOW_FRAGMENT_COUNTS_UNIT) uniform readonly uimage2D uCounts;

layout(location = 0) out vec4 oColour;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint held = min(imageLoad(uCounts, pixel).r, uint(IVSHADOW_MAX_FRAGMENTS_PER_PIXEL));
  if (held == 0u) discard;
  uint own = min(held, fixedLayers);
  uint slot = uint(pixel.y) * width + uint(pixel.x);
  vec4 colours[IVSHADOW_MAX_FRAGMENTS_PER_PIXEL];
  float depths[IVSHADOW_MAX_FRAGMENTS_PER_PIXEL];
  int count = 0;
  uint k = 0u;
  uint next = imageLoad(uHeads, pixel).r;
  while (count < IVSHADOW_MAX_FRAGMENTS_PER_PIXEL) {
    // The pixel's own slots, then its overflow list.
    uint index;
    if (k < own) {
      index = k * pixels + slot;
      ++k;
    } else if (next != kNoFragment) {
      index = next;
      next = fragments[index].next;
    } else {
      break;
    }
    vec4 colour = unpackColour(fragments[index].colour);
    float depth = fragments[index].depth;
    // Insertion by depth; surfaces within kSameLayer of each other (coincident caps, whose
    // depths round differently under another near and far plane) in the order of their
    // colours' bits, so the picture depends neither on which fragment the GPU stored first
    // nor on that rounding.
    uint key = packUnorm4x8(colour);
    int j = count++;
    while (j > 0 && (depths[j - 1] > depth + kSameLayer ||
                     (abs(depths[j - 1] - depth) <= kSameLayer &&
                      packUnorm4x8(colours[j - 1]) > key))) {
      depths[j] = depths[j - 1];
      colours[j] = colours[j - 1];
      --j;
    }
    depths[j] = depth;
    colours[j] = colour;
  }

  vec3 front = vec3(0.0);
  float transmittance = 1.0;
  for (int i = 0; i < count; ++i) {
    front += transmittance * colours[i].a * colours[i].rgb;
    transmittance *= 1.0 - colours[i].a;
  }
  oColour = vec4(front, transmittance);
}
