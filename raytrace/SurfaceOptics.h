#pragma once

#include "callbacks/GlLimits.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ivshadow {

struct TextureImage;

// The CPU twins of deep_shadow_common.glsl: how a surface colours and filters light. The ray
// tracers use them so that only the discretisation differs from the GL path, never the model.

// Opacity within half an 8-bit step of 1 counts as opaque (Coin sends 8-bit colours).
inline bool isOpaque(float alpha) {
  return alpha >= 1.0f - 0.5f / 255.0f;
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
glm::vec3 transmittance(const glm::vec4& c, ShadowColourModel model);

// Coin's texture models (SoMultiTextureImageElement::Model values = GL enums); 0 = none.
glm::vec4 applyTextureModel(const glm::vec4& colour, const glm::vec4& texel, int model,
                            const glm::vec3& blendColour);

// Samples `image` at (s, t) as GL would: nearest or bilinear, repeat or clamp to edge.
glm::vec4 sampleTexture(const TextureImage& image, float s, float t);

}  // namespace ivshadow
