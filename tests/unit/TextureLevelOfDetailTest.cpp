// The traced path's texture filtering against GL's rules (the GL 4.5 spec, 8.14) and Coin's
// choice of them (SoGLImage): the mipmap chain, the level of detail a pixel's footprint gives,
// and the sample taken from the two levels around it.
#include "raytrace/CameraRays.h"
#include "raytrace/SurfaceOptics.h"
#include "scene/SceneTriangles.h"

#include <Inventor/SbLinear.h>
#include <Inventor/SbViewVolume.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ivshadow {
namespace {

TextureImage greyImage(int width, int height, const std::vector<unsigned char>& values) {
  TextureImage image;
  image.width = width;
  image.height = height;
  for (unsigned char v : values) image.rgba.insert(image.rgba.end(), {v, v, v, 255});
  return image;
}

// Coin's SoGLImage: nearest below quality 0.2, bilinear below 0.5, a mipmap chain from 0.5
// (its default) with the nearest texel of each level, bilinear levels from 0.8.
TEST(TextureFiltering, FollowsCoinsQualityLimits) {
  struct Case {
    float quality;
    bool nearest, mipmapped, bilinearLevels;
  };
  for (const Case c : {Case{0.1f, true, false, false}, Case{0.3f, false, false, false},
                       Case{0.5f, false, true, false}, Case{0.9f, false, true, true}}) {
    TextureImage image = greyImage(5, 3, std::vector<unsigned char>(15, 100));
    setTextureFiltering(image, c.quality);
    EXPECT_EQ(image.nearest, c.nearest) << c.quality;
    EXPECT_EQ(image.mipmapped, c.mipmapped) << c.quality;
    EXPECT_EQ(image.bilinearLevels, c.bilinearLevels) << c.quality;
    // 5 x 3 halves to 2 x 1, then 1 x 1, as GL's sizes round down.
    EXPECT_EQ(image.levels.size(), c.mipmapped ? 2u : 0u) << c.quality;
  }
}

// Each level is its parent's 2 x 2 means (an even size), down to the mean of the image.
TEST(TextureFiltering, EachLevelIsTheMeanOfTheOneAbove) {
  TextureImage image = greyImage(4, 4,
                                 {0, 4, 8, 12,     //
                                  16, 20, 24, 28,  //
                                  32, 36, 40, 44,  //
                                  48, 52, 56, 60});
  setTextureFiltering(image, 0.5f);
  ASSERT_EQ(image.levels.size(), 2u);
  const TextureImage::Level& half = image.levels[0];
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 2);
  EXPECT_EQ(half.rgba[0], 10);             // (0 + 4 + 16 + 20) / 4
  EXPECT_EQ(half.rgba[4], 18);             // (8 + 12 + 24 + 28) / 4
  EXPECT_EQ(half.rgba[8], 42);             // (32 + 36 + 48 + 52) / 4
  EXPECT_EQ(half.rgba[12], 50);            // (40 + 44 + 56 + 60) / 4
  EXPECT_EQ(image.levels[1].rgba[0], 30);  // the mean of all 16
  EXPECT_EQ(image.levels[1].rgba[3], 255);
}

// A 2 x 2 checkerboard: magnified (level of detail up to 0.5 for a nearest-texel chain) it is
// sampled bilinearly at level 0; minified, the nearest texel of level 0 and level 1's grey
// (the mean, 127.5 rounded to 128) are blended by the fraction; past the last level, level 1.
TEST(TextureFiltering, MinifiedSamplesBlendTheTwoNearestLevels) {
  TextureImage image = greyImage(2, 2, {0, 255, 255, 0});
  setTextureFiltering(image, 0.5f);
  const float grey = 128.0f / 255.0f;
  const float black = 0.0f;
  // At the centre of texel (0, 0), black, and a quarter of the way to the next texel.
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.25f, 0.25f, 0.4f).r, black);
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.375f, 0.25f, 0.4f).r, 0.25f) << "bilinear";
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.375f, 0.25f, 0.75f).r, 0.75f * grey)
      << "the nearest texel (black), a quarter, and level 1";
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.25f, 0.25f, 1.0f).r, grey);
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.25f, 0.25f, 7.0f).r, grey);
  // Bilinear levels switch to minification at 0, and sample each level bilinearly.
  setTextureFiltering(image, 0.9f);
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.375f, 0.25f, 0.4f).r, 0.6f * 0.25f + 0.4f * grey);
  // Without mipmaps, any level of detail samples level 0.
  setTextureFiltering(image, 0.3f);
  EXPECT_FLOAT_EQ(sampleTexture(image, 0.375f, 0.25f, 3.0f).r, 0.25f);
}

// A square of side 1 textured once across (s, t = x, y), with a 64 x 32 image: a footprint of
// 0.1 across and up spans 6.4 texels in s and 3.2 in t; the level of detail is log2 of the
// larger, whichever way the footprint turns in the plane.
TEST(TextureFiltering, TheLevelOfDetailIsLog2OfTheTexelsAPixelSpans) {
  TextureImage image = greyImage(64, 32, std::vector<unsigned char>(64 * 32, 0));
  const glm::vec3 corners[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const glm::vec2 st[3] = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_FLOAT_EQ(textureLod(image, corners, st, {0.1f, 0, 0}, {0, 0.1f, 0}), std::log2(6.4f));
  EXPECT_FLOAT_EQ(textureLod(image, corners, st, {0, 0.1f, 0}, {0.1f, 0, 0}), std::log2(6.4f));
  // A footprint of 0.1 along the diagonal: 6.4 / sqrt 2 texels in s and 3.2 / sqrt 2 in t.
  const float d = 0.1f / std::sqrt(2.0f);
  EXPECT_NEAR(textureLod(image, corners, st, {d, d, 0}, {-d, d, 0}),
              std::log2(std::hypot(6.4f, 3.2f) / std::sqrt(2.0f)), 1e-5f);
  // The texture repeated 4 times across: 4 times the texels, two levels more.
  const glm::vec2 repeated[3] = {{0, 0}, {4, 0}, {0, 4}};
  EXPECT_FLOAT_EQ(textureLod(image, corners, repeated, {0.1f, 0, 0}, {0, 0.1f, 0}),
                  std::log2(25.6f));
  // A triangle without area has no texture gradient.
  const glm::vec3 line[3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_EQ(textureLod(image, line, st, {0.1f, 0, 0}, {0, 0.1f, 0}), 0.0f);
}

// Seen head-on from distance d through a perspective camera of height angle h, a pixel of a
// picture H pixels high covers 2 d tan(h / 2) / H on a plane parallel to the picture.
TEST(TextureFiltering, APixelsFootprintHeadOnIsItsSizeAtTheDistance) {
  const float distance = 5.0f, angle = 0.8f;
  const int width = 120, height = 80;
  SbViewVolume volume;
  volume.perspective(angle, float(width) / float(height), 1.0f, 20.0f);
  volume.translateCamera(SbVec3f(0.0f, 0.0f, distance));
  SbMatrix viewing, projection;
  volume.getMatrices(viewing, projection);
  const CameraRays rays(viewing, projection, width, height, {glm::vec3(0.0f)});
  const float pixel = 2.0f * distance * std::tan(angle / 2.0f) / float(height);
  for (const auto [x, y] : {std::pair{60, 40}, std::pair{3, 77}}) {
    const CameraRay ray = rays.ray(x, y);
    const glm::vec3 point = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
    const auto [across, up] = rays.footprint(ray, point, glm::vec3(0.0f, 0.0f, 1.0f));
    // Floats over a picture of this size: a few ulps of the pixel's size.
    EXPECT_NEAR(across.x, pixel, 1e-5f) << x << ", " << y;
    EXPECT_NEAR(across.y, 0.0f, 1e-5f);
    EXPECT_NEAR(up.y, pixel, 1e-5f);
    EXPECT_NEAR(up.x, 0.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace ivshadow
