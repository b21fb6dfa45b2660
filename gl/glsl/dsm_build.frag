// One peel of one face of a map (a cube's or a one-face map's, gl/MapFrame.h). The depth test keeps the nearest surface behind the previous
// layer; this shader drops everything at or in front of that layer and multiplies the
// visibility after it by the surface's transmittance (seeds/000 §5). With uOpaqueOnly (the
// closing pass, when a face's layers run out with surfaces left behind them) only opaque
// surfaces are kept, and no light passes them.
in vec3 vPosition;
in vec4 vColour;
in vec2 vTexCoord;

uniform sampler2D uPreviousDepth;
uniform sampler2D uPreviousVisibility;
uniform sampler2D uTexture;
uniform int uTextureModel;
uniform vec3 uTextureBlendColour;
uniform int uColourModel;
// The distance stored is dot(p - uDepthOrigin, uDepthAxis): along the face's axis from the
// light, or from the plane where a directional light's map begins.
uniform vec3 uDepthOrigin;
uniform vec3 uDepthAxis;
// Written as the fragment's depth (scaled by this power of two, DeepShadowMap.cpp), so the
// depth test orders by the same distances as the peel.
uniform float uDepthScale;
// The first triangle of this draw among all the casters' triangles: with gl_PrimitiveID it
// numbers each triangle once.
uniform int uFirstTriangle;
uniform int uOpaqueOnly;

layout(std430, binding = IVSHADOW_MAP_FLAGS_BINDING) buffer PeelFlags {
  uint anyFragment;
  uint transparentFragment;
};

layout(location = 0) out float oDepth;
layout(location = 1) out vec4 oVisibility;
layout(location = 2) out float oPeelDepth;
layout(location = 3) out vec4 oPeelVisibility;

void main() {
  vec4 colour = vColour;
  if (uTextureModel != kTextureNone)
    colour = applyTextureModel(colour, texture(uTexture, vTexCoord), uTextureModel,
                               uTextureBlendColour);
  // A fully clear surface changes nothing; dropping it keeps it from using up a layer.
  if (colour.a <= 0.0) discard;

  // Never below 0, where the written depth would be clamped and surfaces there would tie in
  // the depth test (an orthographic face's near plane lies on the nearest caster); the lists
  // (dsm_list.frag) clamp alike, so both order by the same distances.
  float depth = max(dot(vPosition - uDepthOrigin, uDepthAxis), 0.0);
  ivec2 texel = ivec2(gl_FragCoord.xy);
  // Layers go in order of (distance, triangle number): a surface lying exactly on the
  // previous layer's (a cone's base on a cylinder's top) is the next layer when its triangle
  // comes later, instead of being lost to the tie. Among the rest, the depth test keeps the
  // nearest, and of equally near ones the first drawn, which is the lowest numbered.
  // Stored as the bits of a positive normal float (the smallest exponent's bit added): such
  // floats compare as their bits do, exactly for any count of triangles, and none is a
  // denormal that could be flushed to zero.
  float triangle = intBitsToFloat((uFirstTriangle + gl_PrimitiveID) + 0x00800000);
  vec4 previous = texelFetch(uPreviousVisibility, texel, 0);
  float previousDepth = texelFetch(uPreviousDepth, texel, 0).r;
  if (depth < previousDepth || (depth == previousDepth && triangle <= previous.a)) discard;
  gl_FragDepth = depth * uDepthScale;

  if (uOpaqueOnly != 0 && !isOpaque(colour.a)) discard;
  vec3 visibility = uOpaqueOnly != 0
                        ? vec3(0.0)
                        : previous.rgb * transmittance(clamp(colour, 0.0, 1.0), uColourModel);
  anyFragment = 1u;
  // A surface that lets light through may have more surfaces behind it that matter.
  if (!isOpaque(colour.a)) transparentFragment = 1u;

  oDepth = depth;
  oVisibility = vec4(visibility, 1.0);
  oPeelDepth = depth;
  oPeelVisibility = vec4(visibility, triangle);
}
