// SoDeepShadowLight's VOLUMES method where it differs from RAYS: a camera standing inside a
// shadow volume, what is drawn again when, and textured casters. The analytic pictures, a
// camera inside the group and agreement with the exact reference hold for both methods and
// are tested for both (tests/gl/RayShadowTest.cpp, ScreenShadows*).
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ivshadow::test {
namespace {

// Per-pixel float shading, the sums of log transmittance in 32-bit floats and their exp
// stored as a 16-bit float (relative error 1e-3, a quarter step at most) rounded once to
// 8 bits: one step bounds it, the 1/255.
constexpr double kTolerance = 1.0;

ShadowScene withVolumes(ShadowScene scene) {
  scene.method = "VOLUMES";
  return scene;
}

TEST(ShadowVolumes, ACameraInsideAVolumeSeesTheShadowItStandsIn) {
  // The red glass (half size 0.3, 0.5 above the floor, the light 1 above) shadows a square
  // of half size 0.6 on the floor; its volume at z = 0.3 is 0.42 wide each way. A camera
  // there looking down sees the floor within 0.3 tan(0.3) = 0.093 of its foot: all of it in
  // the shadow, with no volume face between the camera and the floor. z-pass counting would
  // find the floor outside every volume here.
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene = withVolumes(scene);
  std::string text = scene.text();
  const std::string camera =
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n";
  ASSERT_NE(text.find(camera), std::string::npos) << text;
  const double cx = 0.05, cy = 0.02, cz = 0.3, heightAngle = 0.6;
  text.replace(text.find(camera), camera.size(),
               "  PerspectiveCamera { position 0.05 0.02 0.3 nearDistance 0.05 farDistance 5 "
               "heightAngle 0.6 }\n");
  const Image image = renderIv(text, ShadowScene::kSize);
  const std::array<double, 3> red = transmittance(kRedGlass, ColourModel::Saturate);
  const double half = ShadowScene::kSize / 2.0;
  const std::string failure = compareWithExpectation(
      image,
      [&](int px, int py) {
        const double x = cx + ((px + 0.5) / half - 1.0) * std::tan(heightAngle / 2.0) * cz;
        const double y = cy + (1.0 - (py + 0.5) / half) * std::tan(heightAngle / 2.0) * cz;
        Expectation e;
        e.checked = true;
        const double lambert = 255.0 / std::sqrt(1.0 + x * x + y * y);
        for (int c = 0; c < 3; ++c) e.rgb[std::size_t(c)] = lambert * red[std::size_t(c)];
        return e;
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(ShadowVolumes, NoBvhNoMapNoRaysAndAMovedLightDrawsAgain) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene = withVolumes(scene);
  SoSeparator* root = readIv(scene.text());
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  for (int i = 0; i < 2; ++i) renderer->render(root);
  DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  ASSERT_EQ(stats.lights.size(), 1u);
  EXPECT_EQ(stats.lights[0].method, "VOLUMES");
  EXPECT_EQ(stats.lights[0].bytes, 0u);
  EXPECT_EQ(stats.bvhBuilds, 0);
  EXPECT_EQ(stats.raysTraced, 0u);
  EXPECT_EQ(stats.rayFrames, 1);  // nothing moved: drawn once
  // The glass and the floor are one quad of two triangles each: two caps a triangle and the
  // quad's four outer edges (the diagonal cancels).
  EXPECT_EQ(stats.volumeFaces, 2u * (2u * 2u + 4u * 2u));

  auto* lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  ASSERT_NE(lamp, nullptr);
  lamp->location.setValue(0.2f, 0.0f, 1.0f);
  renderer->render(root);
  stats = collectDeepShadowStatistics(root);
  EXPECT_EQ(stats.rayFrames, 2);
  EXPECT_EQ(stats.rayCaptures, 1);  // the view did not move: the surfaces are drawn against again
  // The moved light's shadow: the glass's square, half size 0.3 / (1 - 0.5) = 0.6, centred
  // where the line from (0.2, 0, 1) through the glass's centre (0, 0, 0.5) meets the floor,
  // x = -0.2.
  const Image image = renderer->read();
  root->unref();
  const std::array<double, 3> red = transmittance(kRedGlass, ColourModel::Saturate);
  const std::string failure = compareWithExpectation(
      image,
      [&](int px, int py) {
        const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
        Expectation e;
        // Not checked: the floor's rim, the shadow's edges and where the glass is seen.
        const double extent = std::max(std::abs(x + 0.2), std::abs(y));
        if (std::max(std::abs(x), std::abs(y)) > 0.98 || std::abs(extent - 0.6) < 0.02 ||
            std::max(std::abs(x), std::abs(y)) < 0.32)
          return e;
        e.checked = true;
        const double dx = 0.2 - x, length = std::sqrt(1.0 + dx * dx + y * y);
        for (int c = 0; c < 3; ++c)
          e.rgb[std::size_t(c)] = 255.0 / length * (extent < 0.6 ? red[std::size_t(c)] : 1.0);
        return e;
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(ShadowVolumes, ATexturedCasterCastsItsMeanColourAndSaysSoOnce) {
  // The checkerboard glass is half opaque, half clear texels: its volume lets half through.
  ShadowScene scene;
  scene.filters = {checkerboardFilter()};
  scene = withVolumes(scene);
  SoSeparator* root = readIv(scene.text());  // initialises Coin and the plugin first
  CoinMessageCapture capture;  // after Coin's initialisation, which installs its own handlers
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  // A moved light draws the volumes again from the same casters: no second warning.
  static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"))->location.setValue(0, 0, 1.0001f);
  renderer->render(root);
  static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"))->location.setValue(0, 0, 1);
  renderer->render(root);
  EXPECT_EQ(collectDeepShadowStatistics(root).rayFrames, 3);
  const Image image = renderer->read();
  root->unref();
  std::size_t warned = 0;
  std::string all;
  for (const auto& message : capture.messages()) {
    all += message.raw + "\n";
    if (message.raw.find("method VOLUMES: 2 of the casters' triangles") != std::string::npos)
      ++warned;
  }
  EXPECT_EQ(warned, 1u) << all;
  // Under the glass's shadow (half size 0.6), outside where the glass itself is seen.
  const int px = int((0.45 + 1.2) * 100.0), py = int((1.2 - 0.15) * 100.0);
  const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
  const double expected = 0.5 * 255.0 / std::sqrt(1.0 + x * x + y * y);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.pixel(px, py)[c], expected, kTolerance);
}

}  // namespace
}  // namespace ivshadow::test
