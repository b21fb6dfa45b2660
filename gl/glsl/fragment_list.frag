// The one geometry pass of order-independent transparency by fragment lists (after
// lighting.glsl and fragment_list_common.glsl): every transparent fragment in front of the
// opaque picture is shaded once, with the group's shadows, and stored in its pixel's slots or
// overflow list. The depth test against the opaque pass's depth (less, no writes) runs first,
// so hidden and opaque fragments are neither shaded nor stored.
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
  uint k = imageAtomicAdd(uCounts, pixel, 1u);
  if (k >= uint(IVSHADOW_MAX_FRAGMENTS_PER_PIXEL)) {
    crowded = 1u;
    discard;
  }
  uint index;
  if (k < fixedLayers) {
    index = k * pixels + uint(pixel.y) * width + uint(pixel.x);
  } else {
    uint overflow = atomicAdd(overflowUsed, 1u);
    if (overflow >= overflowCapacity) discard;
    index = fixedLayers * pixels + overflow;
    fragments[index].next = imageAtomicExchange(uHeads, pixel, index);
  }
  fragments[index].colour = packColour(clamp(shade(texel), 0.0, 1.0));
  fragments[index].depth = gl_FragCoord.z;
}
