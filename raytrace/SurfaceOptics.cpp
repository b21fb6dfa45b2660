#include "raytrace/SurfaceOptics.h"

#include "scene/SceneTriangles.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
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

// One level of an image's mipmap chain (level 0: the image), with the image's wrapping.
struct LevelView {
  const TextureImage& image;
  int width;
  int height;
  const unsigned char* rgba;

  LevelView(const TextureImage& image, int level)
      : image(image),
        width(level == 0 ? image.width : image.levels[std::size_t(level) - 1].width),
        height(level == 0 ? image.height : image.levels[std::size_t(level) - 1].height),
        rgba(level == 0 ? image.rgba.data() : image.levels[std::size_t(level) - 1].rgba.data()) {}

  glm::vec4 texel(int x, int y) const {
    x = wrap(x, width, image.repeatS);
    y = wrap(y, height, image.repeatT);
    const unsigned char* p = &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
  }

  // Texel centres sit at (i + 0.5) / size, as in GL; Coin's images are stored bottom row
  // first, which is where t = 0 samples.
  glm::vec4 sample(float s, float t, bool nearest) const {
    const float x = s * float(width) - 0.5f;
    const float y = t * float(height) - 0.5f;
    if (nearest) return texel(int(std::floor(x + 0.5f)), int(std::floor(y + 0.5f)));
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = int(x0), iy = int(y0);
    return glm::mix(glm::mix(texel(ix, iy), texel(ix + 1, iy), fx),
                    glm::mix(texel(ix, iy + 1), texel(ix + 1, iy + 1), fx), fy);
  }
};

}  // namespace

glm::vec3 transmittance(const glm::vec4& c, ShadowColourModel model) {
  return shared::transmittance(c, int(model));
}

glm::vec4 applyTextureModel(const glm::vec4& colour, const glm::vec4& texel, int model,
                            const glm::vec3& blendColour) {
  return shared::applyTextureModel(colour, texel, model, blendColour);
}

glm::vec4 sampleTexture(const TextureImage& image, float s, float t, float lod) {
  // GL's switch between magnification and minification (the GL 4.5 spec, 8.14.2): at 0.5 for
  // a nearest-texel chain under a bilinear magnification, else at 0.
  const float magnifiedUpTo = image.bilinearLevels ? 0.0f : 0.5f;
  if (!image.mipmapped || !(lod > magnifiedUpTo))
    return LevelView(image, 0).sample(s, t, image.nearest);
  // Minified: the two levels around the level of detail, blended by its fraction (8.14.3).
  const int last = int(image.levels.size());
  const float clamped = std::min(lod, float(last));
  const int first = int(std::floor(clamped));
  const float fraction = clamped - float(first);
  const bool nearest = !image.bilinearLevels;
  const glm::vec4 near = LevelView(image, first).sample(s, t, nearest);
  if (first == last || fraction == 0.0f) return near;
  return glm::mix(near, LevelView(image, first + 1).sample(s, t, nearest), fraction);
}

float textureLod(const TextureImage& image, const glm::vec3 corners[3],
                 const glm::vec2 texCoords[3], const glm::vec3& across, const glm::vec3& up) {
  const glm::vec3 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0];
  const float a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
  const float det = a * c - b * b;
  if (!(det > 0.0f)) return 0.0f;
  const glm::vec2 size(float(image.width), float(image.height));
  // An offset in the triangle's plane as a combination of its edges, and so the texture
  // coordinates' change along it, in texels.
  const auto texels = [&](const glm::vec3& offset) {
    const float r1 = glm::dot(offset, e1), r2 = glm::dot(offset, e2);
    const float alpha = (c * r1 - b * r2) / det, beta = (a * r2 - b * r1) / det;
    return glm::length(
        (alpha * (texCoords[1] - texCoords[0]) + beta * (texCoords[2] - texCoords[0])) * size);
  };
  const float rho = std::max(texels(across), texels(up));
  return std::isnan(rho) ? 0.0f : std::log2(rho);
}

glm::vec4 texturedColourOf(const glm::vec4& colour, const glm::vec4& texel,
                           const TextureImage& image) {
  const glm::vec3 blend(image.blendColour[0], image.blendColour[1], image.blendColour[2]);
  return applyTextureModel(colour, texel, image.model, blend);
}

}  // namespace ivshadow
