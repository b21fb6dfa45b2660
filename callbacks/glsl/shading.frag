// The camera pass of SoTransparentShadowGroup (after lighting.glsl). Variant
// IVSHADOW_OPAQUE_ONLY is SoPeelingSeparator's opaque pass: it keeps only fully opaque
// fragments, the transparent ones being left to the peel passes (peel.frag).

void main() {
  vec4 texel = coin_texunit0_model != kTextureNone ? texture(textureMap0, gl_TexCoord[0].st)
                                                   : vec4(1.0);
  vec4 colour = shade(texel);
#ifdef IVSHADOW_OPAQUE_ONLY
  if (!isOpaque(colour.a)) discard;
#endif
  gl_FragData[0] = colour;
}
