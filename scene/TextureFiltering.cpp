#include "scene/SceneTriangles.h"

#include <algorithm>
#include <cmath>

namespace ivshadow {
namespace {

// Coin's defaults of SoGLImage's COIN_TEX2_LINEAR_LIMIT, COIN_TEX2_MIPMAP_LIMIT and
// COIN_TEX2_LINEAR_MIPMAP_LIMIT.
constexpr float kFilteredFrom = 0.2f;
constexpr float kMipmappedFrom = 0.5f;
constexpr float kBilinearLevelsFrom = 0.8f;

// The next level down: each texel the mean of the texels of the level above over the same
// area, as GL's generated mipmaps (a linear sample at the texel's centre, which for an even
// size is the mean of a 2 x 2 block), rounded to nearest.
TextureImage::Level halve(int width, int height, const std::vector<unsigned char>& rgba) {
  TextureImage::Level level;
  level.width = std::max(1, width / 2);
  level.height = std::max(1, height / 2);
  level.rgba.resize(std::size_t(level.width) * std::size_t(level.height) * 4);
  const auto at = [&](int x, int y, int c) {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return float(rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4 + std::size_t(c)]);
  };
  for (int j = 0; j < level.height; ++j)
    for (int i = 0; i < level.width; ++i) {
      // The texel's centre in the level above, in its texel coordinates (centres at k + 0.5).
      const float x = (float(i) + 0.5f) * float(width) / float(level.width) - 0.5f;
      const float y = (float(j) + 0.5f) * float(height) / float(level.height) - 0.5f;
      const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
      const float fx = x - float(x0), fy = y - float(y0);
      for (int c = 0; c < 4; ++c) {
        const float value = (1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) +
                            fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c));
        level.rgba[(std::size_t(j) * std::size_t(level.width) + std::size_t(i)) * 4 +
                   std::size_t(c)] = static_cast<unsigned char>(std::lround(value));
      }
    }
  return level;
}

}  // namespace

void setTextureFiltering(TextureImage& image, float quality) {
  image.nearest = quality < kFilteredFrom;
  image.mipmapped = quality >= kMipmappedFrom;
  image.bilinearLevels = quality >= kBilinearLevelsFrom;
  image.levels.clear();
  if (!image.mipmapped) return;
  int width = image.width, height = image.height;
  const std::vector<unsigned char>* above = &image.rgba;
  while (width > 1 || height > 1) {
    image.levels.push_back(halve(width, height, *above));
    width = image.levels.back().width;
    height = image.levels.back().height;
    above = &image.levels.back().rgba;
  }
}

}  // namespace ivshadow
