// Resolves the fragment lists (after fragment_list_common.glsl): each pixel's fragments are
// sorted by depth and composited front to back (seeds/000 eq. 2.5), written as the front
// layers' (rgb, transmittance) that the blend puts over the opaque picture:
// dst = src.rgb + dst * src.a (eq. 2.8), as the peel composite does.
layout(r32ui, binding = IVSHADOW_FRAGMENT_HEADS_UNIT) uniform readonly uimage2D uHeads;

layout(location = 0) out vec4 oColour;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 colours[IVSHADOW_MAX_FRAGMENTS_PER_PIXEL];
  float depths[IVSHADOW_MAX_FRAGMENTS_PER_PIXEL];
  int count = 0;
  for (uint i = imageLoad(uHeads, pixel).r;
       i != kNoFragment && count < IVSHADOW_MAX_FRAGMENTS_PER_PIXEL; i = fragments[i].next) {
    vec4 colour = fragments[i].colour;
    float depth = fragments[i].depth;
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
  if (count == 0) discard;
  vec3 front = vec3(0.0);
  float transmittance = 1.0;
  for (int k = 0; k < count; ++k) {
    front += transmittance * colours[k].a * colours[k].rgb;
    transmittance *= 1.0 - colours[k].a;
  }
  oColour = vec4(front, transmittance);
}
