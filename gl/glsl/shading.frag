// The camera pass of SoTransparentShadowGroup (after lighting.glsl). Variant
// IVSHADOW_OPAQUE_ONLY is depth peeling's opaque pass: it keeps only fully opaque
// fragments, the transparent ones being left to the peel passes (peel.frag), and raises the
// progress flag when it leaves one: a view without any needs no peel pass.

#ifdef IVSHADOW_OPAQUE_ONLY
layout(std430, binding = IVSHADOW_PEEL_PROGRESS_BINDING) buffer PeelProgress {
  uint transparentFragments;  // some fragment was left to the peel passes
};
#endif

void main() {
  beginShading();
  vec4 texel = coin_texunit0_model != kTextureNone ? texture(textureMap0, gl_TexCoord[0].st)
                                                   : vec4(1.0);
#ifdef IVSHADOW_OPAQUE_ONLY
  // The opacity before the lighting, as the peel and list passes test it: a transparent
  // fragment is dropped unshaded, which on a software rasteriser is most of this pass's cost
  // (every layer of glass in front of the floor). The flag is read first: a store from every
  // such fragment to the one word would be as costly.
  float alpha =
      applyTextureModel(gl_Color, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb).a;
  if (!isOpaque(alpha)) {
    if (transparentFragments == 0u) transparentFragments = 1u;
    discard;
  }
#endif
  gl_FragData[0] = shade(texel);
}
