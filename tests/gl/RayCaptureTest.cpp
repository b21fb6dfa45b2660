// What the RAYS method captures again and when: a frame in which only a light moved traces the
// surfaces it captured before; the camera, the viewport or a caster moving captures them
// again. Each case ends in the analytic picture of ShadowScene (not in agreement with an
// earlier frame): a stale capture would put the shadows of the earlier view or geometry there.
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTranslation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

namespace ivshadow::test {
namespace {

// Per-pixel float shading and a float transmittance stored as a 16-bit float (relative error
// 1e-3, a quarter step at most) rounded once to 8 bits: one step bounds it (as in
// RayShadowTest).
constexpr double kTolerance = 1.0;
// Glass composited over the floor: the floor is rounded to 8 bits in the framebuffer before
// the peeled glass layers go over it, and the result is rounded again; half a step more than
// a single surface needs (the worst seen is 1.03).
constexpr double kLayeredTolerance = 1.5;

// The red and green glass over the floor, traced, with a translation before the floor's mesh
// (DEF Lift) that moves the floor, a caster, without touching the lights or the camera.
ShadowScene tracedScene() {
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.method = "RAYS";
  scene.floorNodes = "DEF Lift Translation { translation 0 0 0 }";
  return scene;
}

struct Rendering {
  SoSeparator* root = nullptr;
  std::unique_ptr<CheckedRenderer> renderer;
  SoDeepShadowLight* lamp = nullptr;

  explicit Rendering(const ShadowScene& scene) {
    root = readIv(scene.text());  // initialises Coin and the plugin first
    std::string error;
    renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
    EXPECT_TRUE(renderer) << error;
    lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
    EXPECT_NE(lamp, nullptr);
  }
  ~Rendering() { root->unref(); }
  bool ready() const { return renderer && lamp; }
  DeepShadowStatistics frame() {
    renderer->render(root);
    return collectDeepShadowStatistics(root);
  }
};

// ShadowScene's light is 1 above the floor's centre; frames start with it elsewhere, so that
// moving it back to its place gives the analytic picture.
const SbVec3f kAnalyticLight(0.0f, 0.0f, 1.0f);
const SbVec3f kElsewhere(0.35f, -0.2f, 1.3f);

void expectAnalytic(const Image& image, const ShadowScene& scene) {
  const std::string failure =
      compareWithExpectation(image, ShadowPicture{&scene, ColourModel::Saturate}, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(RayCapture, AMovedLightIsTracedFromTheKeptCaptureAndCastsItsAnalyticShadows) {
  const ShadowScene scene = tracedScene();
  Rendering r(scene);
  ASSERT_TRUE(r.ready());
  r.lamp->location.setValue(kElsewhere);
  DeepShadowStatistics stats = r.frame();
  ASSERT_EQ(stats.rayCaptures, 1);
  EXPECT_EQ(stats.rayLayers, 3);  // the floor and both glasses in front of it
  r.lamp->location.setValue(kAnalyticLight);
  stats = r.frame();
  EXPECT_EQ(stats.rayFrames, 2);    // traced again for the moved light
  EXPECT_EQ(stats.rayCaptures, 1);  // from the surfaces captured in the first frame
  EXPECT_EQ(stats.rayCaptureMs, 0.0);
  EXPECT_EQ(stats.rayLayers, 3);
  expectAnalytic(r.renderer->read(), scene);
}

TEST(RayCapture, AMovedCameraIsCapturedAgain) {
  const ShadowScene scene = tracedScene();
  Rendering r(scene);
  ASSERT_TRUE(r.ready());
  r.lamp->location.setValue(kElsewhere);
  r.frame();
  // The camera outside the group, 0.3 to the right (30 pixels), and the light back in its
  // place: the floor keeps its depth in this orthographic view, so the old capture would
  // match it and shade each pixel with the shadow of the floor point it showed before.
  SoSearchAction search;
  search.setType(SoCamera::getClassTypeId());
  search.apply(r.root);
  ASSERT_NE(search.getPath(), nullptr);
  static_cast<SoCamera*>(search.getPath()->getTail())->position.setValue(0.3f, 0.0f, 5.0f);
  r.lamp->location.setValue(kAnalyticLight);
  const DeepShadowStatistics stats = r.frame();
  EXPECT_EQ(stats.rayCaptures, 2);
  const ShadowPicture picture{&scene, ColourModel::Saturate};
  const std::string failure = compareWithExpectation(
      r.renderer->read(), [&](int x, int y) { return picture(x + 30, y); }, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(RayCapture, AChangedViewportIsCapturedAgain) {
  const ShadowScene scene = tracedScene();
  Rendering r(scene);
  ASSERT_TRUE(r.ready());
  r.lamp->location.setValue(kElsewhere);
  r.frame();
  // Half the size, centred: 50 pixels a unit from (60, 60) on. The old capture is indexed
  // by window coordinates at 100 pixels a unit.
  SbViewportRegion half(ShadowScene::kSize, ShadowScene::kSize);
  half.setViewportPixels(60, 60, 120, 120);
  r.renderer->action().setViewportRegion(half);
  r.lamp->location.setValue(kAnalyticLight);
  const DeepShadowStatistics stats = r.frame();
  EXPECT_EQ(stats.rayCaptures, 2);
  const ShadowPicture picture{&scene, ColourModel::Saturate};
  const std::string failure = compareWithExpectation(
      r.renderer->read(),
      [&](int x, int y) {
        if (x < 60 || x >= 180 || y < 60 || y >= 180) return Expectation{};
        return picture.at(-1.2 + (x - 60 + 0.5) / 50.0, 1.2 - (y - 60 + 0.5) / 50.0, 1.0 / 50.0);
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(RayCapture, AMovedCasterIsCapturedAgain) {
  const ShadowScene scene = tracedScene();
  Rendering r(scene);
  ASSERT_TRUE(r.ready());
  // The floor 0.4 lower first: its captured points lie 0.4 below where it is drawn next, and
  // traced from there they would be in the shadow of the floor itself.
  auto* lift = static_cast<SoTranslation*>(SoNode::getByName("Lift"));
  ASSERT_NE(lift, nullptr);
  lift->translation.setValue(0.0f, 0.0f, -0.4f);
  r.lamp->location.setValue(kElsewhere);
  r.frame();
  lift->translation.setValue(0.0f, 0.0f, 0.0f);
  r.lamp->location.setValue(kAnalyticLight);
  const DeepShadowStatistics stats = r.frame();
  EXPECT_EQ(stats.rayCaptures, 2);
  expectAnalytic(r.renderer->read(), scene);
}

TEST(RayCapture, ALightTurnedOnIsTracedFromTheKeptCaptureIntoNewTextures) {
  // Two traced lights at one place, half the intensity each, the second off in the first
  // frame: turning it on changes only lights, so the kept capture is traced for both, and the
  // shading textures, now sized for two lights, must be given the kept depths again. Their
  // sum is the single light's analytic picture.
  ShadowScene scene = tracedScene();
  scene.lightCount = 2;
  Rendering r(scene);
  ASSERT_TRUE(r.ready());
  auto* second = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp1"));
  ASSERT_NE(second, nullptr);
  second->on = FALSE;
  DeepShadowStatistics stats = r.frame();
  ASSERT_EQ(stats.lights.size(), 1u);
  second->on = TRUE;
  stats = r.frame();
  ASSERT_EQ(stats.lights.size(), 2u);
  EXPECT_EQ(stats.lights[1].method, "RAYS");
  EXPECT_EQ(stats.rayFrames, 2);
  EXPECT_EQ(stats.rayCaptures, 1);
  const Image image = r.renderer->read();
  expectAnalytic(image, scene);
  // Where both glasses are seen over the floor each layer must find its own traced
  // visibility through the kept depths: the red glass (height 0.5) is lit unshadowed, the
  // green one (0.25) through the red, the floor through both. Composited front to back (the
  // group peels exactly) at the opacity GL gets, 128/255 (Coin sends colours as 8-bit
  // values), Lambert from the light 1 above the centre.
  const std::array<double, 3> red = transmittance(kRedGlass, ColourModel::Saturate);
  const std::array<double, 3> green = transmittance(kGreenGlass, ColourModel::Saturate);
  const std::string failure = compareWithExpectation(
      image,
      [&](int x, int y) {
        Expectation e;
        const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
        // Inside the red glass, clear of the shadow edges on the green glass and floor.
        if (std::max(std::abs(px), std::abs(py)) > 0.25) return e;
        const double r2 = px * px + py * py;
        const double litRed = 255.0 * 0.5 / std::sqrt(0.25 + r2);
        const double litGreen = 255.0 * 0.75 / std::sqrt(0.5625 + r2);
        const double litFloor = 255.0 / std::sqrt(1.0 + r2);
        const double a = 128.0 / 255.0;
        for (std::size_t c = 0; c < 3; ++c) {
          const double floor = litFloor * red[c] * green[c];
          const double greenGlass = litGreen * kGreenGlass.diffuse[c] * red[c];
          const double redGlass = litRed * kRedGlass.diffuse[c];
          e.rgb[c] = a * redGlass + (1.0 - a) * (a * greenGlass + (1.0 - a) * floor);
        }
        e.checked = true;
        return e;
      },
      kLayeredTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

}  // namespace
}  // namespace ivshadow::test
