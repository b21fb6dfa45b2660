#pragma once

// What the traced group's GL tests share (GroupTracerTest, GroupTracerMotionTest): full
// traced frames of a ShadowScene, and a scene kept with its renderer across frames.
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow::test {

// The tracer shades and composites in floats (the reference's code) and the picture is
// blended once onto a black framebuffer in 32-bit floats, then rounded to 8 bits: one step.
inline constexpr double kTolerance = 1.0;

// Every frame traced in full (movingResolution 1): these tests count and check full frames;
// the reduced frames of a motion have tests of their own below.
inline ShadowScene traced(ShadowScene scene) {
  scene.renderer = "TRACER";
  scene.groupFields += " movingResolution 1";
  return scene;
}

// A blue square drawn by GL (BASE_COLOR) before or after the group, at height `z` over the
// floor's left part: x in [left, right], y in [-0.95, 0.95].
inline std::string blueSquare(double z, double left = -0.95, double right = -0.6) {
  const std::string h = " " + std::to_string(z), l = std::to_string(left) + " ",
                    r = std::to_string(right) + " ";
  return "Separator { LightModel { model BASE_COLOR } BaseColor { rgb 0 0 1 } "
         "Coordinate3 { point [ " +
         l + "-0.95" + h + ", " + r + "-0.95" + h + ", " + r + "0.95" + h + ", " + l + "0.95" + h +
         " ] } FaceSet { numVertices 4 } }";
}

// The analytic picture away from the square (ten pixels' margin); inside it, blue or the
// floor as `blueThere` says.
inline ExpectedImage squareOrFloor(const ShadowScene& scene, bool blueThere) {
  const ShadowPicture floor{&scene, ColourModel::Saturate};
  return [floor, blueThere](int px, int py) {
    const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
    const bool inside = x > -0.85 && x < -0.7 && std::fabs(y) < 0.85;
    const bool away = x > -0.5 || x < -1.05 || std::fabs(y) > 1.05;
    if (inside && blueThere) return Expectation{true, {0.0, 0.0, 255.0}};
    if (inside || away) return floor(px, py);
    return Expectation{};
  };
}

struct Rendering {
  SoSeparator* root = nullptr;
  std::unique_ptr<CheckedRenderer> renderer;
  SoDeepShadowLight* lamp = nullptr;
  std::unique_ptr<CoinMessageCapture> capture;  // with captureMessages

  explicit Rendering(const ShadowScene& scene, bool captureMessages = false) {
    root = readIv(scene.text());
    // After the read, which initialises Coin, which sets its handlers.
    if (captureMessages) capture = std::make_unique<CoinMessageCapture>();
    std::string error;
    renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
    EXPECT_TRUE(renderer) << error;
    lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  }
  ~Rendering() { root->unref(); }
  // The messages captured so far whose text holds every one of `parts`.
  int messagesWith(const std::vector<std::string>& parts) const {
    int found = 0;
    for (const CoinMessageCapture::Message& message : capture->messages())
      found += std::all_of(parts.begin(), parts.end(), [&](const std::string& part) {
        return message.text.find(part) != std::string::npos;
      });
    return found;
  }
  DeepShadowStatistics frame() {
    renderer->render(root);
    return collectDeepShadowStatistics(root);
  }
  void expectAnalytic(const ShadowScene& scene, const char* when) {
    renderer->render(root);
    const std::string failure = compareWithExpectation(
        renderer->read(), ShadowPicture{&scene, ColourModel::Saturate}, kTolerance);
    EXPECT_TRUE(failure.empty()) << when << ": " << failure;
  }
};

}  // namespace ivshadow::test
