#include "image_files/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/CoinMessageCapture.h"
#include "scene_input/SceneLoader.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/LitPlane.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace ivshadow::test {
namespace {

const Filter kRedGlass{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Largest channel difference per pixel between two images of the same size.
std::vector<int> pixelDifferences(const Image& a, const Image& b) {
  std::vector<int> out;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]));
      out.push_back(worst);
    }
  return out;
}

TEST(ShadowGroup, WithoutDeepShadowLightsItLooksLikeCoin) {
  // The whole bundled scene, camera included, wrapped in a group without deep shadow lights
  // whose other lights do not cast.
  const std::string plain = readFile(scenesDir() + "/shading_features.iv");
  const std::string wrapped =
      "#Inventor V2.1 ascii\nTransparentShadowGroup {\ncastingLights DEEP_SHADOW_LIGHTS\n" +
      plain.substr(plain.find('\n') + 1) + "\n}\n";
  const Image coin = renderIv(plain, 300);
  const Image group = renderIv(wrapped, 300);
  const std::vector<int> differences = pixelDifferences(coin, group);
  int within2 = 0, worst = 0;
  for (int d : differences) {
    within2 += d <= 2 ? 1 : 0;
    worst = std::max(worst, d);
  }
  // Coin lights per vertex, the group per pixel; everything else is the same. On the scene's
  // 1/16-unit grids the interpolation error of the diffuse terms stays within 2 steps; the
  // narrow specular peak under the point light (exponent 12.8) is underestimated by Gouraud
  // interpolation by up to 8 steps over a few hundred pixels.
  const double share = double(within2) / double(differences.size());
  if (share < 0.99 || worst > 8) {
    writePng(outputDir() + "/coin.png", coin);
    writePng(outputDir() + "/group.png", group);
  }
  EXPECT_GE(share, 0.99) << "images in " << outputDir();
  EXPECT_LE(worst, 8) << "images in " << outputDir();
}

// A half-transparent square seen from behind (its vertices run clockwise seen from the camera
// and the light), under shape hints that turn two-sided lighting on: its back face is lit as a
// front face would be. Expected, from LitPlane's geometry (the square spans the 2 x 2 plane):
// alpha 0.5 over the black background gives half of Lambert's 255 / sqrt(1 + r^2) at distance
// r from the light's foot. In every frame and under both of Coin's blending types: the second
// frame, and every frame under DELAYED_BLEND, once lit the back face by nothing (the shading
// program's coin_two_sided_lighting stayed 0 when GL already had two-sided lighting on).
TEST(ShadowGroup, TwoSidedLightingHoldsInEveryFrameAndTransparencyType) {
  init();
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
      "  TransparentShadowGroup {\n"
      "    DeepShadowLight { location 0 0 1 }\n"
      "    ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType UNKNOWN_SHAPE_TYPE }\n"
      "    Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0"
      " transparency 0.5 }\n"
      "    Coordinate3 { point [ -1 -1 0, -1 1 0, 1 1 0, 1 -1 0 ] }\n"
      "    FaceSet { numVertices 4 }\n"
      "  }\n}\n";
  SoSeparator* root = readIv(text);
  const LitPlane lambert;
  const auto halfLit = [&lambert](int x, int y) {
    Expectation e = lambert(x, y);
    for (double& channel : e.rgb) channel *= 0.5;
    return e;
  };
  for (const auto type : {SoGLRenderAction::BLEND, SoGLRenderAction::DELAYED_BLEND}) {
    std::string error;
    auto renderer = CheckedRenderer::create(LitPlane::kSize, LitPlane::kSize, error);
    ASSERT_TRUE(renderer) << error;
    renderer->action().setTransparencyType(type);
    for (int frame = 1; frame <= 3; ++frame) {
      renderer->render(root);
      // The group lights per pixel: Lambert's value to within 8-bit rounding of the shade
      // and of the blend, one step.
      const std::string failure = compareWithExpectation(renderer->read(), halfLit, 1.0);
      EXPECT_TRUE(failure.empty())
          << "transparency type " << int(type) << ", frame " << frame << ": " << failure;
    }
  }
  root->unref();
}

TEST(ShadowGroup, DeepShadowLightOutsideAGroupIsAPointLight) {
  std::string scene = readFile(scenesDir() + "/lit_plane.iv");
  const Image pointLight = renderIv(scene, LitPlane::kSize);
  scene.replace(scene.find("PointLight"), std::string("PointLight").size(), "DeepShadowLight");
  const Image deepLight = renderIv(scene, LitPlane::kSize);
  const std::vector<int> differences = pixelDifferences(pointLight, deepLight);
  EXPECT_EQ(*std::max_element(differences.begin(), differences.end()), 0);
}

// A group on the left half, and after it a plain lit plane with a transparent square on the
// right half: what follows the group must render exactly as it does after a plain separator.
std::string groupThenPlainScene(bool active) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
     << "  TransparentShadowGroup { isActive " << (active ? "TRUE" : "FALSE") << "\n"
     << "    DeepShadowLight { location -0.6 0 1 }\n"
     << "    Material { diffuseColor 1 0 0 transparency 0.5 }\n"
     << "    Coordinate3 { point [ -0.8 -0.2 0.5, -0.4 -0.2 0.5, -0.4 0.2 0.5, -0.8 0.2 0.5 ] }\n"
     << "    FaceSet { numVertices 4 }\n"
     << "    Material { diffuseColor 1 1 1 transparency 0 }\n"
     << "    Coordinate3 { point [ -1.1 -1 0, -0.1 -1 0, -0.1 1 0, -1.1 1 0 ] }\n"
     << "    FaceSet { numVertices 4 }\n"
     << "  }\n"
     << "  Separator {\n"
     << "    PointLight { location 0.6 0 1 }\n"
     << "    Material { diffuseColor 0.2 0.6 1 specularColor 0.5 0.5 0.5 shininess 0.3 }\n"
     << "    Coordinate3 { point [ 0.1 -1 0, 1.1 -1 0, 1.1 1 0, 0.1 1 0 ] }\n"
     << "    FaceSet { numVertices 4 }\n"
     << "    Texture2 { image 2 1 4 0xFFFFFF80 0xFF00FFFF }\n"
     << "    Material { diffuseColor 1 1 1 transparency 0.3 }\n"
     << "    Cube { width 0.5 height 0.5 depth 0.1 }\n"
     << "  }\n}\n";
  return iv.str();
}

TEST(ShadowGroup, ShapesAfterTheGroupRenderAsAfterAPlainSeparator) {
  const Image active = renderIv(groupThenPlainScene(true), 240);
  const Image inactive = renderIv(groupThenPlainScene(false), 240);
  int leftDifferent = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 240; ++x) {
      const bool right = x >= 130;  // the plain part: x > 0.1 units
      for (int c = 0; c < 4; ++c) {
        if (right)
          ASSERT_EQ(active.pixel(x, y)[c], inactive.pixel(x, y)[c]) << "pixel " << x << "," << y;
        else if (active.pixel(x, y)[c] != inactive.pixel(x, y)[c])
          ++leftDifferent;
      }
    }
  EXPECT_GT(leftDifferent, 1000) << "the active group should have shadowed its own floor";
}

TEST(ShadowGroup, FourLightsInOneGroup) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene.lightCount = 4;
  SoNode* root = nullptr;
  const Image image = renderIv(scene.text(), ShadowScene::kSize, &root);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  root->unref();
  ASSERT_EQ(stats.lights.size(), 4u);
  for (const auto& light : stats.lights) EXPECT_EQ(light.layersUsed[5], 2);
  // Four lights of a quarter intensity each at one place add up to the one-light picture
  // (each contribution rounds only once, at the end).
  const std::string failure =
      compareWithExpectation(image, ShadowPicture{&scene, ColourModel::Saturate}, 1.0);
  EXPECT_TRUE(failure.empty()) << failure;
}

// Two lights in sibling separators, each over its own half of the floor with its own glass:
// Coin gives both the same GL light number (the first separator's light is popped before the
// second's is pushed). Each half must look exactly as it does when its separator is alone in
// the group, so each light's shadows come from its own map.
std::string siblingLights(bool left, bool right) {
  auto half = [](double x) {
    std::ostringstream iv;
    iv << "    Separator {\n"
       << "      DeepShadowLight { location " << x << " 0 1 }\n"
       << "      Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
       << "      Coordinate3 { point [ " << x - 0.55 << " -1 0, " << x + 0.55 << " -1 0, "
       << x + 0.55 << " 1 0, " << x - 0.55 << " 1 0 ] }\n"
       << "      FaceSet { numVertices 4 }\n"
       << "      Material { diffuseColor " << (x < 0 ? "1 0 0" : "0 0 1") << " transparency 0.5 }\n"
       << "      Coordinate3 { point [ " << x - 0.2 << " -0.2 0.5, " << x + 0.2 << " -0.2 0.5, "
       << x + 0.2 << " 0.2 0.5, " << x - 0.2 << " 0.2 0.5 ] }\n"
       << "      FaceSet { numVertices 4 }\n    }\n";
    return iv.str();
  };
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
         "  TransparentShadowGroup {\n" +
         (left ? half(-0.6) : std::string()) + (right ? half(0.6) : std::string()) + "  }\n}\n";
}

TEST(ShadowGroup, LightsInSiblingSeparatorsKeepTheirOwnMaps) {
  const Image both = renderIv(siblingLights(true, true), 240);
  const Image left = renderIv(siblingLights(true, false), 240);
  const Image right = renderIv(siblingLights(false, true), 240);
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 240; ++x) {
      const Image& alone = x < 120 ? left : right;
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(both.pixel(x, y)[c], alone.pixel(x, y)[c]) << "pixel " << x << "," << y;
    }
  // And each half does show its shadow: under the glass's edge the floor is tinted.
  EXPECT_GT(both.pixel(60 - 30, 120)[0], both.pixel(60 - 30, 120)[2] + 20);
}

TEST(ShadowGroup, ShadowStyleDecidesWhoCastsAndWhoReceives) {
  ShadowScene scene;
  Filter noCaster = kRedGlass;
  noCaster.nodes = "ShadowStyle { style NO_SHADOWING }";
  scene.filters = {noCaster};
  Filter clear = kRedGlass;
  clear.transparency = 1.0;
  ShadowScene unshadowed = scene;
  unshadowed.filters = {clear};
  // A filter that does not cast leaves the floor as if it were not there.
  ShadowPicture picture{&unshadowed, ColourModel::Saturate};
  {
    const Image image = renderIv(scene.text(), ShadowScene::kSize);
    const std::string failure = compareWithExpectation(image, picture, 1.0);
    EXPECT_TRUE(failure.empty()) << failure;
  }
  // A floor that casts but is not SHADOWED is drawn by Coin without the program: no shadow.
  // Coin lights it per vertex, hence the fine grid (see LitPlane.h for the error bound).
  ShadowScene notReceiving;
  notReceiving.filters = {kRedGlass};
  notReceiving.floorNodes = "ShadowStyle { style CASTS_SHADOW }";
  notReceiving.floorCells = 32;
  ShadowScene expected = notReceiving;
  expected.filters = {clear};
  const Image image = renderIv(notReceiving.text(), ShadowScene::kSize);
  const std::string failure =
      compareWithExpectation(image, ShadowPicture{&expected, ColourModel::Saturate}, 1.0);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(ShadowGroup, MapsAreRebuiltOnlyWhenSomethingUnderTheGroupChanged) {
  init();
  ShadowScene scene;
  scene.filters = {kRedGlass};
  SoSeparator* root = readIv(scene.text());
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  auto rebuilds = [&] { return collectDeepShadowStatistics(root).rebuilds; };

  for (int frame = 0; frame < 3; ++frame) renderer->render(root);
  EXPECT_EQ(rebuilds(), 1) << "an unchanged scene re-renders without rebuilding";

  SoSearchAction findCamera;
  findCamera.setType(SoOrthographicCamera::getClassTypeId());
  findCamera.apply(root);
  ASSERT_NE(findCamera.getPath(), nullptr);
  static_cast<SoOrthographicCamera*>(findCamera.getPath()->getTail())->height = 2.6f;
  renderer->render(root);
  EXPECT_EQ(rebuilds(), 1) << "moving the camera needs no new map";

  auto* lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  ASSERT_NE(lamp, nullptr);
  lamp->location.setValue(0.0f, 0.0f, 1.0f);  // same value: Coin still notifies
  lamp->location.setValue(0.1f, 0.0f, 1.0f);
  renderer->render(root);
  EXPECT_EQ(rebuilds(), 2) << "moving the light rebuilds its map";

  SoSearchAction findMaterial;
  findMaterial.setType(SoMaterial::getClassTypeId());
  findMaterial.setInterest(SoSearchAction::LAST);
  findMaterial.apply(root);
  ASSERT_NE(findMaterial.getPath(), nullptr);
  static_cast<SoMaterial*>(findMaterial.getPath()->getTail())->transparency = 0.2f;
  renderer->render(root);
  EXPECT_EQ(rebuilds(), 3) << "changing a caster rebuilds the maps";
  renderer.reset();
  root->unref();
}

TEST(ShadowGroup, OutOfRangeFieldsAreClampedWithOneWarningEach) {
  init();
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene.lightFields = "resolution 0 maxLayers -3";
  SoSeparator* root = readIv(scene.text());
  auto* lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  ASSERT_NE(lamp, nullptr);
  lamp->bias = std::nanf("");  // the file format cannot spell NaN; an application can
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  std::vector<std::string> warnings;
  {
    CoinMessageCapture capture;
    renderer->render(root);
    lamp->touch();  // forces a rebuild, which resolves the fields again
    renderer->render(root);
    EXPECT_EQ(collectDeepShadowStatistics(root).rebuilds, 2);
    for (const auto& message : capture.messages())
      if (message.raw.find("SoDeepShadowLight") != std::string::npos)
        warnings.push_back(message.raw);
  }
  const Image image = renderer->read();
  renderer.reset();
  root->unref();
  std::string all;
  for (const auto& w : warnings) all += w + "\n";
  ASSERT_EQ(warnings.size(), 3u) << "one warning per field, although built twice:\n" << all;
  EXPECT_NE(all.find("\"Lamp\": field resolution is 0, outside 1.."), std::string::npos) << all;
  EXPECT_NE(all.find("field maxLayers is -3, outside 1..64; using 1"), std::string::npos) << all;
  EXPECT_NE(all.find("field bias is not a finite number; using 0.1"), std::string::npos) << all;
  // Clamped, the light still renders, through a map of one texel a face: the floor far
  // outside the glass's shadow gets the -z face's only texel, which looks through the glass
  // (Extremes.ResolutionOneGivesTheCentreTexelToTheWholeFace): Lambert times the red glass's
  // (1 - a) clamp(1 - a + c), 0.5 0.25 0.25.
  const double lambert = 255.0 / std::sqrt(1.0 + 0.955 * 0.955);
  EXPECT_NEAR(image.pixel(230 - 15, 120)[0], 0.5 * lambert, 2.0);
  EXPECT_NEAR(image.pixel(230 - 15, 120)[1], 0.25 * lambert, 2.0);
}

}  // namespace
}  // namespace ivshadow::test
