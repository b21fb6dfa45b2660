// Coin's texture coordinate functions that GL generates (TextureCoordinatePlane,
// TextureCoordinateEnvironment) reach GL as glTexGen state, which only the fixed-function
// pipeline applies; inside a group the shapes are drawn by the group's shading programs,
// which compute the coordinates themselves (nodes/TexGenWatchElement.h). The answers here
// are plain Coin's fixed-function pictures of the same shapes without a group (Coin's and
// Mesa's code, none of the plugin's), and for the plane an analytic one.
#include "image_files/ImageComparison.h"
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

constexpr int kSize = 120;

// An orthographic camera over x, y in [-1.2, 1.2]; `wrapper` opens the node that holds `body`
// ("Separator {" for plain Coin, a group or a peeling separator for the plugin).
std::string sceneWith(const std::string& wrapper, const std::string& body) {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  OrthographicCamera { position 0 0 5 height 2.4 nearDistance 1 farDistance 10 }\n"
         "  DirectionalLight { direction 0 0 -1 }\n  " +
         wrapper + "\n" + body + "\n  }\n}\n";
}

// Unlit (BASE_COLOR, white), so that the colours are the texels alone; nearest texels
// (textureQuality below 0.5 turns filtering off), so that no filtering differs. A 2 x 2
// texture: red, green / blue, white.
const std::string kTexture =
    "    LightModel { model BASE_COLOR }\n"
    "    BaseColor { rgb 1 1 1 }\n"
    "    Complexity { textureQuality 0.1 }\n"
    "    Texture2 { image 2 2 3 0xff0000 0x00ff00 0x0000ff 0xffffff }\n";
const std::string kQuad =
    "    Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n"
    "    FaceSet { numVertices 4 }\n";
const std::string kPlane = "    TextureCoordinatePlane { directionS 0.5 0 0 directionT 0 0.5 0 }\n";

const char* const kWrappers[] = {
    "TransparentShadowGroup { renderer RASTER DeepShadowLight { location 0 0 4 }",
    "TransparentShadowGroup { renderer RASTER method MAP DeepShadowLight { location 0 0 4 }",
    // Coin's blending: after the RAYS captures, Coin's state brings back the camera pass's
    // program, not the last variant the group bound.
    "TransparentShadowGroup { renderer RASTER transparency COIN_BLENDING DeepShadowLight { "
    "location 0 0 4 }",
    "PeelingSeparator { method FRAGMENT_LISTS",
};
// The defaults, AUTO, which trace on a software rasteriser.
const char* const kTracedWrappers[] = {
    "TransparentShadowGroup { DeepShadowLight { location 0 0 4 }",
    "PeelingSeparator {",
};

// Both pictures come from the same per-vertex coordinates interpolated by the same
// rasteriser; the shading program's arithmetic in float may move a texel boundary by a
// fraction of a pixel, so a few pixels on a boundary may take the texel beside.
void expectSameAsPlainCoin(const std::string& body, bool traced = true) {
  const Image plain = renderIv(sceneWith("Separator {", body), kSize);
  std::vector<const char*> wrappers(std::begin(kWrappers), std::end(kWrappers));
  if (traced)
    wrappers.insert(wrappers.end(), std::begin(kTracedWrappers), std::end(kTracedWrappers));
  for (const char* wrapper : wrappers) {
    const Image drawn = renderIv(sceneWith(wrapper, body), kSize);
    const ImageComparison c = ImageComparison::compare(drawn, plain, "plugin", "plain Coin");
    EXPECT_LE(c.all.shareAbove2, 0.005) << wrapper << ": largest error " << c.all.maxError
                                        << " at (" << c.maxErrorX << ", " << c.maxErrorY << ")";
  }
}

TEST(TextureCoordinateFunction, PlaneInsideAGroupIsPlainCoinsAndTheAnalyticPicture) {
  const std::string body = kTexture + kPlane + kQuad;
  expectSameAsPlainCoin(body);
  // s = 0.5 x, t = 0.5 y, repeated: texel column floor(2 s) mod 2, row floor(2 t) mod 2.
  const Image drawn = renderIv(sceneWith(kWrappers[0], body), kSize);
  const std::array<std::array<int, 3>, 4> texels = {
      {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}}};
  int checked = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const double x = -1.2 + (px + 0.5) * 2.4 / kSize, y = 1.2 - (py + 0.5) * 2.4 / kSize;
      // Off the quad, and two pixels either side of a texel boundary (x or y = 0).
      if (std::abs(x) > 0.98 || std::abs(y) > 0.98 || std::abs(x) < 0.04 || std::abs(y) < 0.04)
        continue;
      const int column = int(std::floor(x)) & 1, row = int(std::floor(y)) & 1;
      const std::array<int, 3>& expected = texels[std::size_t(row * 2 + column)];
      const std::uint8_t* pixel = drawn.pixel(px, py);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(pixel[c], expected[std::size_t(c)], 1) << "pixel " << px << ", " << py;
      ++checked;
    }
  EXPECT_GT(checked, kSize * kSize / 2);
}

// GL's sphere map, from each vertex's eye-space position and normal, on every path: the tracer
// and the reference compute it as GL does (Coin's own software function reflects the normal
// alone, and its picture differed on 2.5 % of the pixels).
TEST(TextureCoordinateFunction, EnvironmentMapOnASphereIsPlainCoins) {
  expectSameAsPlainCoin(kTexture + "    TextureCoordinateEnvironment { }\n    Sphere { }\n");
}

// The sphere map follows the camera: a traced group reads the coordinates again when the
// camera moves, and its picture stays plain Coin's from there.
TEST(TextureCoordinateFunction, AnEnvironmentMapFollowsAMovedCamera) {
  const std::string body = kTexture + "    TextureCoordinateEnvironment { }\n    Sphere { }\n";
  const std::string moved = "position 0.6 0.3 5";
  const auto atMovedCamera = [&](const std::string& wrapper) {
    std::string text = sceneWith(wrapper, body);
    text.replace(text.find("position 0 0 5"), std::string("position 0 0 5").size(), moved);
    return text;
  };
  const Image plain = renderIv(atMovedCamera("Separator {"), kSize);
  SoSeparator* root = readIv(sceneWith(kTracedWrappers[0], body));
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  static_cast<SoOrthographicCamera*>(root->getChild(0))->position = SbVec3f(0.6f, 0.3f, 5.0f);
  renderer->render(root);
  const ImageComparison c = ImageComparison::compare(renderer->read(), plain, "traced", "plain");
  // As expectSameAsPlainCoin: a texel boundary may move by a fraction of a pixel.
  EXPECT_LE(c.all.shareAbove2, 0.005) << "largest error " << c.all.maxError;
  renderer.reset();
  root->unref();
}

// The function ends with its separator: the shape after it takes Coin's default coordinates
// (the texture stretched over its bounding box), in the group as in plain Coin.
TEST(TextureCoordinateFunction, AFunctionEndsWithItsSeparator) {
  expectSameAsPlainCoin(kTexture + "    Separator { " + kPlane +
                        "      Coordinate3 { point [ -1 -1 0, 0 -1 0, 0 1 0, -1 1 0 ] }\n"
                        "      FaceSet { numVertices 4 } }\n"
                        "    Coordinate3 { point [ 0 -1 0, 1 -1 0, 1 1 0, 0 1 0 ] }\n"
                        "    FaceSet { numVertices 4 }\n");
}

// Half transparent: peeled inside a group and in a peeling separator, blended by plain Coin;
// one layer over black composites the same either way.
TEST(TextureCoordinateFunction, PeeledTransparentShapesUseTheFunctionToo) {
  expectSameAsPlainCoin(kTexture + "    Material { diffuseColor 1 1 1 transparency 0.5 }\n" +
                        kPlane + kQuad);
}

// A SoShadowStyle that does not receive switches the group's program off where the function
// is set, and the next one switches it on again for the shape, without a bind.
TEST(TextureCoordinateFunction, AShadowStyleBetweenTheFunctionAndTheShapeKeepsIt) {
  expectSameAsPlainCoin(kTexture + "    ShadowStyle { style CASTS_SHADOW }\n" + kPlane +
                        "    ShadowStyle { style CASTS_SHADOW_AND_SHADOWED }\n" + kQuad);
}

// Frames after the first, render caching on inside the group: the sixth frame is still plain
// Coin's. (Measured: here Coin does not replay that separator's cache even without the
// element's invalidation, since the group's passes change the state it depends on; the
// invalidation in TexGenWatchElement::setElt is for caches that would replay.)
TEST(TextureCoordinateFunction, RenderCachesInsideTheGroupKeepTheFunction) {
  const std::string body =
      kTexture + "    Separator { renderCaching ON\n" + kPlane + kQuad + "    }\n";
  const Image plain = renderIv(sceneWith("Separator {", body), kSize);
  init();
  SoSeparator* root = readIv(sceneWith(kWrappers[0], body));
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  ASSERT_TRUE(renderer) << error;
  for (int frame = 0; frame < 6; ++frame) renderer->render(root);
  const ImageComparison c =
      ImageComparison::compare(renderer->read(), plain, "sixth frame", "plain Coin");
  EXPECT_LE(c.all.shareAbove2, 0.005) << "largest error " << c.all.maxError;
  root->unref();
}

}  // namespace
}  // namespace ivshadow::test
