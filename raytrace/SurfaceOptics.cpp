#include "raytrace/SurfaceOptics.h"

#include "scene/SceneTriangles.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include <cmath>

namespace ivshadow {
namespace {

// The formulas the GLSL programs evaluate, compiled from their text: glm's names are GLSL's.
namespace shared {
using glm::clamp;
using glm::mix;
using glm::pow;
using glm::vec3;
using glm::vec4;
constexpr int kColourMonochrome = int(ShadowColourModel::Monochrome);
constexpr int kColourSaturate = int(ShadowColourModel::Saturate);
constexpr int kColourPower = int(ShadowColourModel::Power);
#include "scene/surface_optics.glsl"
}  // namespace shared

int wrap(int i, int size, bool repeat) {
  if (repeat) {
    const int m = i % size;
    return m < 0 ? m + size : m;
  }
  return i < 0 ? 0 : i >= size ? size - 1 : i;
}

glm::vec4 texel(const TextureImage& image, int x, int y) {
  x = wrap(x, image.width, image.repeatS);
  y = wrap(y, image.height, image.repeatT);
  const unsigned char* p =
      &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
  return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

}  // namespace

glm::vec3 transmittance(const glm::vec4& c, ShadowColourModel model) {
  return shared::transmittance(c, int(model));
}

glm::vec4 applyTextureModel(const glm::vec4& colour, const glm::vec4& texel, int model,
                            const glm::vec3& blendColour) {
  return shared::applyTextureModel(colour, texel, model, blendColour);
}

glm::vec4 sampleTexture(const TextureImage& image, float s, float t) {
  // Texel centres sit at (i + 0.5) / size, as in GL; Coin's images are stored bottom row
  // first, which is where t = 0 samples.
  const float x = s * float(image.width) - 0.5f;
  const float y = t * float(image.height) - 0.5f;
  if (image.nearest) return texel(image, int(std::floor(x + 0.5f)), int(std::floor(y + 0.5f)));
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  const int ix = int(x0), iy = int(y0);
  return glm::mix(glm::mix(texel(image, ix, iy), texel(image, ix + 1, iy), fx),
                  glm::mix(texel(image, ix, iy + 1), texel(image, ix + 1, iy + 1), fx), fy);
}

glm::vec4 texturedColourOf(const glm::vec4& colour, const glm::vec4& texel,
                           const TextureImage& image) {
  const glm::vec3 blend(image.blendColour[0], image.blendColour[1], image.blendColour[2]);
  return applyTextureModel(colour, texel, image.model, blend);
}

}  // namespace ivshadow
