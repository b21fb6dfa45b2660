// One draw of one face of an opacity map (seeds/002; gl/OpacityMap.h), after
// dsm_build.vert. A transparent fragment's absorption, -log of its transmittance per channel,
// is added (additive blending) to the slice its distance falls in and to every slice after it,
// so that slice k holds the absorption of everything up to its far end: a lookup then reads
// three slices, not all of them. Its slice also takes the fragment's slice coordinate as the
// first surface there (alpha, minimum blending). An opaque surface offers its distance to the
// opaque surfaces' depth (minimum blending) and touches no slice. Neither depth test nor
// culling: the light crosses every surface, front or back, as in the reference. Sums of
// absorption never saturate, unlike the document's 8-bit sums of absorbed light, which is why
// it kept each slice's own share instead.
in vec3 vPosition;
in vec4 vColour;
in vec2 vTexCoord;

uniform sampler2D uTexture;
uniform int uTextureModel;
uniform vec3 uTextureBlendColour;
uniform int uColourModel;
uniform vec3 uDepthOrigin;  // the stored distance is dot(p - uDepthOrigin, uDepthAxis)
uniform vec3 uDepthAxis;
// The distances the slices divide uniformly, and their count.
uniform float uSliceNear;
uniform float uSliceFar;
uniform int uSlices;
uniform int uFirstSlice;  // the slice attachment 1 holds in this draw

const int kSlicesPerDraw = IVSHADOW_OPACITY_SLICES_PER_DRAW;

layout(location = 0) out float oOpaqueDepth;
layout(location = 1) out vec4 oSlice[kSlicesPerDraw];

void main() {
  vec4 colour = vColour;
  if (uTextureModel != kTextureNone)
    colour = applyTextureModel(colour, texture(uTexture, vTexCoord), uTextureModel,
                               uTextureBlendColour);
  colour = clamp(colour, 0.0, 1.0);
  if (colour.a <= 0.0) discard;  // lets all light through
  float depth = dot(vPosition - uDepthOrigin, uDepthAxis);
  bool opaque = isOpaque(colour.a);
  oOpaqueDepth = opaque ? depth : IVSHADOW_OPACITY_NO_OPAQUE;
  // The slice coordinate: 0 at uSliceNear, 1 at uSliceFar, slice k covering [k, k + 1) / N.
  float s = (depth - uSliceNear) / (uSliceFar - uSliceNear);
  int slice = clamp(int(floor(s * float(uSlices))), 0, uSlices - 1);
  vec3 absorption = opaque ? vec3(0.0)
                           : -log(max(transmittance(colour, uColourModel),
                                      vec3(IVSHADOW_MIN_TRANSMITTANCE)));
  vec4 elsewhere = vec4(0.0, 0.0, 0.0, IVSHADOW_OPACITY_EMPTY_SLICE);
  for (int i = 0; i < kSlicesPerDraw; ++i) {
    int at = uFirstSlice + i;
    oSlice[i] = opaque || at < slice
                    ? elsewhere
                    : vec4(absorption, at == slice ? s : IVSHADOW_OPACITY_EMPTY_SLICE);
  }
}
