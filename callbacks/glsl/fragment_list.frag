// The one geometry pass of order-independent transparency by fragment lists (after
// lighting.glsl and fragment_list_common.glsl): every transparent fragment in front of the
// opaque picture is shaded once, with the group's shadows, and linked into its pixel's list.
// The depth test against the opaque pass's depth (less, no writes) runs first, so hidden and
// opaque fragments are neither shaded nor stored.
layout(early_fragment_tests) in;

layout(r32ui, binding = IVSHADOW_FRAGMENT_HEADS_UNIT) uniform coherent uimage2D uHeads;
layout(r32ui, binding = IVSHADOW_FRAGMENT_COUNTS_UNIT) uniform coherent uimage2D uCounts;

void main() {
  beginShading();
  vec4 texel = coin_texunit0_model != kTextureNone ? texture(textureMap0, gl_TexCoord[0].st)
                                                   : vec4(1.0);
  float alpha =
      applyTextureModel(gl_Color, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb).a;
  // Opaque fragments were drawn by the opaque pass; a clear one changes nothing.
  if (isOpaque(alpha) || alpha <= 0.0) discard;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (imageAtomicAdd(uCounts, pixel, 1u) >= uint(IVSHADOW_MAX_FRAGMENTS_PER_PIXEL)) {
    crowded = 1u;
    discard;
  }
  uint index = atomicAdd(used, 1u);
  if (index >= capacity) discard;
  fragments[index].colour = shade(texel);
  fragments[index].depth = gl_FragCoord.z;
  fragments[index].next = imageAtomicExchange(uHeads, pixel, index);
}
