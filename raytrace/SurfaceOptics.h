#pragma once

#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ivshadow {

struct TextureImage;

// The CPU side of scene/surface_optics.glsl: how a surface colours and filters light. The ray
// tracers use them so that only the discretisation differs from the GL path, never the model.

// Opacity within half an 8-bit step of 1 counts as opaque (kOpaqueAlpha).
inline bool isOpaque(float alpha) {
  return alpha >= kOpaqueAlpha;
}

// Whether two hits of one shape along a ray, at ray parameters a and b, are one surface met
// twice (Embree reports a triangle again after a spatial split, and a ray through a shared
// edge meets both triangles): float intersection puts them within about 1e-7 of each other,
// relatively, so 2e-6 separates them from any real second surface but a coincident one.
inline bool sameSurface(float a, float b) {
  const float larger = a > b ? a : b;
  return (a > b ? a - b : b - a) <= 2e-6f * larger;
}

// Fraction of light per channel that passes a surface of colour c.rgb and opacity c.a.
IVSHADOW_INTERNAL glm::vec3 transmittance(const glm::vec4& c, ShadowColourModel model);

// Coin's texture models (SoMultiTextureImageElement::Model values = GL enums); 0 = none.
IVSHADOW_INTERNAL glm::vec4 applyTextureModel(const glm::vec4& colour, const glm::vec4& texel,
                                              int model, const glm::vec3& blendColour);

// Samples `image` at (s, t) as GL would: nearest or bilinear, repeat or clamp to edge, and
// where the image is mipmapped and `lod` (log2 of the texels one pixel spans) minifies it,
// from its mipmap chain.
IVSHADOW_INTERNAL glm::vec4 sampleTexture(const TextureImage& image, float s, float t,
                                          float lod = 0.0f);

// GL's texture level of detail (the GL 4.5 spec, 8.14.1) where a pixel's footprint on a
// triangle is `across` and `up` (world offsets to where the next pixels' rays meet its plane,
// CameraRays::footprint): log2 of the larger length, in texels of `image`, of the texture
// coordinates' change over them. The triangle's corners and their coordinates give that
// change; 0 for a triangle without area.
IVSHADOW_INTERNAL float textureLod(const TextureImage& image, const glm::vec3 corners[3],
                                   const glm::vec2 texCoords[3], const glm::vec3& across,
                                   const glm::vec3& up);

// What a triangle shows at barycentrics (u, v) of corners 1 and 2: its corners' colour and
// opacity interpolated, and with a texture the texel at the interpolated coordinates.
struct SurfaceSample {
  glm::vec4 colour{1.0f};
  glm::vec4 texel{1.0f};
};
// Inline, as texturedColour: the tracer asks for each surface a camera ray meets.
inline SurfaceSample sampleSurface(const glm::vec4 colours[3], const glm::vec2 texCoords[3],
                                   const TextureImage* image, float u, float v, float lod = 0.0f) {
  const float w = 1.0f - u - v;
  SurfaceSample sample;
  sample.colour = w * colours[0] + u * colours[1] + v * colours[2];
  if (image != nullptr) {
    const glm::vec2 st = w * texCoords[0] + u * texCoords[1] + v * texCoords[2];
    sample.texel = sampleTexture(*image, st.x, st.y, lod);
  }
  return sample;
}
// The sample's colour after the image's texture model, as Coin's fixed-function texturing and
// the shading program apply it.
IVSHADOW_INTERNAL glm::vec4 texturedColourOf(const glm::vec4& colour, const glm::vec4& texel,
                                             const TextureImage& image);
// The same, or the colour itself without an image: inline, as most surfaces have none and the
// tracer asks several times for each surface a camera ray meets.
inline glm::vec4 texturedColour(const glm::vec4& colour, const glm::vec4& texel,
                                const TextureImage* image) {
  return image == nullptr ? colour : texturedColourOf(colour, texel, *image);
}

}  // namespace ivshadow
