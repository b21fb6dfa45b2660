// Depth peeling of SoPeelingSeparator (seeds/000 §2, Bavoil & Myers 2008), after
// lighting.glsl. Targets: 0 the depth range still to peel (-near, far) under MAX blending,
// 1 the front layers blended "under" (rgb, 1 - transmittance), 2 this pass's back layer.
// Every fragment passes the previous values through, so MAX keeps them where no fragment of
// this pass changes them. Variants: IVSHADOW_PEEL_INIT, the first pass (the depth range of
// the transparent fragments); IVSHADOW_PEEL_DUAL, the nearest and the farthest layer per
// pass; neither, one layer per pass, nearest first.

// The depth test against the opaque picture (less, no writes) runs before shading, so hidden
// and opaque fragments cost nothing. The camera pass must not do so: there a discarded
// fragment must not write depth.
layout(early_fragment_tests) in;

uniform sampler2D uPeelDepth;
uniform sampler2D uPeelFront;
layout(std430, binding = IVSHADOW_PEEL_PROGRESS_BINDING) buffer PeelProgress {
  uint deeperLayers;  // some fragment lies strictly inside the range still to peel
};

#ifdef IVSHADOW_PEEL_DUAL
const bool kDual = true;
#else
const bool kDual = false;
#endif

void peel(vec4 texel, float alpha) {
  float z = gl_FragCoord.z;
  // Opaque fragments were drawn in the opaque pass. Transparent ones behind them never get
  // here: the early depth test against the opaque depth drops them.
  if (isOpaque(alpha)) discard;
#ifdef IVSHADOW_PEEL_INIT
  gl_FragData[0] = vec4(-z, z, 0.0, 0.0);
  gl_FragData[1] = vec4(0.0);
  gl_FragData[2] = vec4(0.0);
  deeperLayers = 1u;
#else
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 range = texelFetch(uPeelDepth, pixel, 0).xy;
  float near = -range.x;
  float far = kDual ? range.y : 2.0;
  vec4 front = texelFetch(uPeelFront, pixel, 0);
  gl_FragData[0] = vec4(-1.0, -1.0, 0.0, 0.0);
  gl_FragData[1] = front;
  gl_FragData[2] = vec4(0.0);
  if (z < near - kSameLayer || z > far + kSameLayer) return;  // peeled in an earlier pass
  bool onNear = abs(z - near) <= kSameLayer, onFar = abs(z - far) <= kSameLayer;
  if (!onNear && !onFar) {
    gl_FragData[0].xy = vec2(-z, kDual ? z : -1.0);
    deeperLayers = 1u;
    return;
  }
  vec4 colour = shade(texel);
  if (onNear) {
    float transmittance = 1.0 - front.a;
    gl_FragData[1] = vec4(front.rgb + colour.rgb * colour.a * transmittance,
                          1.0 - transmittance * (1.0 - colour.a));
  } else {
    gl_FragData[2] = colour;
  }
#endif
}

void main() {
  beginShading();
  vec4 texel = coin_texunit0_model != kTextureNone ? texture(textureMap0, gl_TexCoord[0].st)
                                                   : vec4(1.0);
  // The opacity alone decides what a peel pass does; most fragments need no shading.
  float alpha =
      applyTextureModel(gl_Color, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb).a;
  peel(texel, alpha);
}
