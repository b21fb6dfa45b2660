// The one geometry pass of a deep shadow map face built from fragment lists (after
// dsm_list_common.glsl): every surface the face sees is linked into its texel's list with its
// distance, its triangle and the light it lets through. No depth test and no colour: the
// resolve (dsm_list_resolve.comp) orders them as the peel passes of dsm_build.frag would.
in vec3 vPosition;
in vec4 vColour;
in vec2 vTexCoord;

uniform sampler2D uTexture;
uniform int uTextureModel;
uniform vec3 uTextureBlendColour;
uniform int uColourModel;
uniform vec3 uDepthOrigin;
uniform vec3 uDepthAxis;
uniform int uFirstTriangle;

layout(r32ui, binding = IVSHADOW_FRAGMENT_HEADS_UNIT) uniform coherent uimage2D uHeads;

void main() {
  vec4 colour = vColour;
  if (uTextureModel != kTextureNone)
    colour = applyTextureModel(colour, texture(uTexture, vTexCoord), uTextureModel,
                               uTextureBlendColour);
  // A fully clear surface changes nothing and takes no layer, as in the peel.
  if (colour.a <= 0.0) discard;
  uint index = atomicAdd(used, 1u);
  if (index >= capacity) discard;
  fragments[index].transmittance =
      vec4(transmittance(clamp(colour, 0.0, 1.0), uColourModel), isOpaque(colour.a) ? 1.0 : 0.0);
  // Never below 0, as the peel stores it (dsm_build.frag).
  fragments[index].depth = max(dot(vPosition - uDepthOrigin, uDepthAxis), 0.0);
  fragments[index].triangle = uint(uFirstTriangle + gl_PrimitiveID);
  fragments[index].next = imageAtomicExchange(uHeads, ivec2(gl_FragCoord.xy), index);
}
