// SoTransparentShadowGroup renderer TRACER while things move: the reduced frames of a motion
// (movingResolution) and their refinement, and what a motion keeps for the frames after it.
// Every picture is checked against an expectation computed without the tracer (ShadowScene's
// analytic picture), or against a fresh read of the scene.
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/CoinClock.h"
#include "tests/gl/ShadowScene.h"
#include "tests/gl/TracedRendering.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/sensors/SoNodeSensor.h>
#include <Inventor/sensors/SoSensorManager.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

namespace ivshadow::test {
namespace {

// A camera's motion keeps no surfaces (the next frame's rays do not meet them): a light moved
// after it traces the camera rays again, and the picture is the analytic one.
TEST(TracedGroup, ALightMovedAfterACamerasMotionTracesTheCameraRaysAgain) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  auto* camera = static_cast<SoCamera*>(r.root->getChild(0));
  const SbVec3f eye = camera->position.getValue();
  r.frame();
  const SbVec3f place = r.lamp->location.getValue();
  r.lamp->location = place + SbVec3f(0.05f, 0.0f, 0.0f);
  r.frame();  // the first change keeps the surfaces its camera rays met
  r.lamp->location = place;
  EXPECT_EQ(r.frame().tracerCameraRays, 0u) << "a light's move after a light's move";
  for (const float step : {0.05f, 0.1f, 0.0f}) {
    camera->position = eye + SbVec3f(step, 0.0f, 0.0f);
    EXPECT_EQ(r.frame().tracerCameraRays, std::uint64_t(ShadowScene::kSize * ShadowScene::kSize));
  }
  r.lamp->location = place + SbVec3f(0.05f, 0.0f, 0.0f);
  EXPECT_EQ(r.frame().tracerCameraRays, std::uint64_t(ShadowScene::kSize * ShadowScene::kSize))
      << "the motion kept no surfaces to shade again";
  r.lamp->location = place;
  r.expectAnalytic(scene, "the light back after the motion");
  EXPECT_EQ(collectDeepShadowStatistics(r.root).tracerCameraRays, 0u)
      << "the frame after the motion kept its surfaces";
}

// A light whose intensity changes, not its place, asks the same shadow rays of the same
// casters: their answers are taken again, none is traced, and the picture is the one a fresh
// read of the scene at that intensity draws. A light moved after it traces its rays.
TEST(TracedGroup, ALightsIntensityAloneTracesNoShadowRayAgain) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  const SbVec3f place = r.lamp->location.getValue();
  r.frame();
  r.lamp->location = place + SbVec3f(0.05f, 0.0f, 0.0f);
  r.frame();  // the first change keeps the surfaces and their shadow rays' answers
  r.lamp->location = place;
  ASSERT_GT(r.frame().raysTraced, 0u);
  r.lamp->intensity = 0.6f;
  const DeepShadowStatistics dimmed = r.frame();
  EXPECT_EQ(dimmed.tracerFrames, 4);
  EXPECT_EQ(dimmed.raysTraced, 0u) << "the answers were taken again";
  const Image kept = r.renderer->read();
  Rendering fresh(scene);
  fresh.lamp->intensity = 0.6f;
  EXPECT_GT(fresh.frame().raysTraced, 0u);
  const Image expected = fresh.renderer->read();
  EXPECT_EQ(
      std::memcmp(kept.data(), expected.data(), std::size_t(kept.width()) * kept.height() * 4), 0)
      << "the same answers give the same picture";
  r.lamp->location = place + SbVec3f(0.0f, 0.05f, 0.0f);
  EXPECT_GT(r.frame().raysTraced, 0u) << "a moved light asks other rays";
}

// The analytic picture where it is flat: pixels whose every neighbour within `radius` has the
// same expected colour (within one step). A picture traced at a lower resolution and
// stretched is exact there, whatever its filter; nearer an edge it blends both sides.
ExpectedImage flatParts(const ExpectedImage& exact, int radius) {
  return [exact, radius](int px, int py) {
    const Expectation centre = exact(px, py);
    if (!centre.checked) return Expectation{};
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const int x = px + dx, y = py + dy;
        if (x < 0 || y < 0 || x >= ShadowScene::kSize || y >= ShadowScene::kSize)
          return Expectation{};
        const Expectation near = exact(x, y);
        if (!near.checked) return Expectation{};
        for (int c = 0; c < 3; ++c)
          if (std::fabs(near.rgb[std::size_t(c)] - centre.rgb[std::size_t(c)]) > 1.0)
            return Expectation{};
      }
    return centre;
  };
}

// Pixels further than one step from their analytic value.
int pixelsOff(const Image& image, const ExpectedImage& exact) {
  int off = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Expectation e = exact(x, y);
      if (!e.checked) continue;
      for (int c = 0; c < 3; ++c)
        if (std::fabs(double(image.pixel(x, y)[c]) - e.rgb[std::size_t(c)]) > kTolerance) {
          ++off;
          break;
        }
    }
  return off;
}

TEST(TracedGroup, AMotionIsTracedAtMovingResolutionAndStillnessRefinesIt) {
  ShadowScene scene = traced(ShadowScene{});
  scene.groupFields += " movingResolution 0.25";
  scene.filters = {kRedGlass, kGreenGlass};
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  const ShadowPicture exact{&scene, ColourModel::Saturate};
  const SbVec3f place = r.lamp->location.getValue();
  constexpr int kReduced = ShadowScene::kSize / 4;  // 240 x 0.25

  // The first frame has nothing before it to move from: traced in full.
  DeepShadowStatistics stats = r.frame();
  EXPECT_EQ(stats.tracerWidth, ShadowScene::kSize);
  EXPECT_EQ(stats.tracerHeight, ShadowScene::kSize);

  // The light moves on two frames running: the first is traced in full (a single edit is
  // never blurred), the second at a quarter of the size.
  r.lamp->location = SbVec3f(0.35f, -0.2f, 1.3f);
  stats = r.frame();
  EXPECT_EQ(stats.tracerWidth, ShadowScene::kSize) << "the first frame of a motion";
  r.lamp->location = place;
  stats = r.frame();
  EXPECT_EQ(stats.tracerWidth, kReduced);
  EXPECT_EQ(stats.tracerHeight, kReduced);
  EXPECT_EQ(stats.tracerRefines, 0);
  const Image moving = r.renderer->read();
  // The stretched picture is the exact one where the picture is flat over a reduced pixel and
  // its neighbours (4 pixels each, so 6 either side covers the filter's reach) ...
  const std::string flat = compareWithExpectation(moving, flatParts(exact, 6), kTolerance);
  EXPECT_TRUE(flat.empty()) << "the moving frame: " << flat;
  // ... and coarser at the shadows' edges: a full trace is within one step everywhere (the
  // refined frame below), while a quarter-size one blurs every shadow and pane edge over
  // about 4 pixels, and those edges run for hundreds of pixels: over 100 pixels off.
  EXPECT_GT(pixelsOff(moving, exact), 100) << "the moving frame is not coarser";

  // Nothing moves for a quarter of a second (Coin's clock moved on, CoinClock.h): the group
  // asks for a frame through Coin's timer queue, without reading its subgraph again.
  SoNodeSensor redraw;
  redraw.attach(r.root);
  advanceCoinClock(0.25);
  SoDB::getSensorManager()->processTimerQueue();
  EXPECT_TRUE(redraw.isScheduled()) << "the group did not ask for the refined frame";
  redraw.detach();
  stats = r.frame();
  EXPECT_EQ(stats.tracerRefines, 1);
  EXPECT_EQ(stats.tracerWidth, ShadowScene::kSize);
  EXPECT_EQ(stats.tracerScenes, 1) << "asking for the refined frame re-read the subgraph";
  const std::string refined = compareWithExpectation(r.renderer->read(), exact, kTolerance);
  EXPECT_TRUE(refined.empty()) << "the refined frame: " << refined;
  const int traced = stats.tracerFrames;
  EXPECT_EQ(r.frame().tracerFrames, traced) << "a still frame after the refined one traces";
  // After the refined frame a new motion starts in full again.
  r.lamp->location = SbVec3f(0.35f, -0.2f, 1.3f);
  EXPECT_EQ(r.frame().tracerWidth, ShadowScene::kSize) << "the first frame after the refined one";
}

// The traced group's request for its refined frame is a notification that changes nothing:
// a group around it (RASTER, whose map the lamp inside casts) does not build its map again.
TEST(TracedGroup, AskingForTheRefinedFrameRebuildsNoEnclosingGroup) {
  ShadowScene scene = traced(ShadowScene{});
  scene.groupFields += " movingResolution 0.25";
  scene.filters = {kRedGlass};
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  auto* outer = new SoTransparentShadowGroup;
  // Not peeling: a peeling group draws the groups inside it as part of its own peeling.
  outer->transparency = SoTransparentShadowGroup::COIN_BLENDING;
  while (r.root->getNumChildren() > 0) {
    outer->addChild(r.root->getChild(0));
    r.root->removeChild(0);
  }
  r.root->addChild(outer);
  const SbVec3f place = r.lamp->location.getValue();
  r.frame();
  r.lamp->location = SbVec3f(0.35f, -0.2f, 1.3f);
  r.frame();
  r.lamp->location = place;
  ASSERT_EQ(r.frame().tracerReduced, 1);
  const int builds = outer->getStatistics().rebuilds;
  advanceCoinClock(0.25);  // a quarter of a second still (CoinClock.h)
  SoDB::getSensorManager()->processTimerQueue();
  EXPECT_EQ(r.frame().tracerRefines, 1);
  EXPECT_EQ(outer->getStatistics().rebuilds, builds) << "the enclosing group built its map again";
}

TEST(TracedGroup, AReducedFrameStillEndsAtWhatGlDrewBefore) {
  ShadowScene scene = traced(ShadowScene{});
  scene.groupFields += " movingResolution 0.25";
  scene.filters = {kRedGlass, kGreenGlass};
  // Nearer the camera than the floor and the glass, its sides off the reduced pixels' edges
  // (1.5 pixels in), so that a reduced pixel straddles them.
  scene.aboveGroup = blueSquare(0.75, -0.935, -0.585);
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  const SbVec3f place = r.lamp->location.getValue();
  r.frame();
  r.lamp->location = SbVec3f(0.35f, -0.2f, 1.3f);
  r.frame();
  r.lamp->location = place;
  ASSERT_EQ(r.frame().tracerWidth, ShadowScene::kSize / 4);
  // The square stays whole to its edges, x in [-0.935, -0.585] and y in [-0.95, 0.95] (every
  // pixel whose centre lies inside by a tenth of a pixel); away from it and from the
  // shadows' edges, the floor.
  const ExpectedImage floor = flatParts(squareOrFloor(scene, true), 6);
  const std::string failure = compareWithExpectation(
      r.renderer->read(),
      [&floor](int px, int py) {
        const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
        if (x > -0.934 && x < -0.586 && std::fabs(y) < 0.949)
          return Expectation{true, {0.0, 0.0, 255.0}};
        return floor(px, py);
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(TracedGroup, AMovingResolutionOutOfRangeIsNamedAndClamped) {
  ShadowScene scene = traced(ShadowScene{});
  scene.groupFields += " movingResolution 0";
  scene.filters = {kRedGlass};
  Rendering r(scene, true);
  ASSERT_TRUE(r.renderer && r.lamp);
  r.frame();
  // Two moves running: the second is a reduced frame.
  DeepShadowStatistics stats;
  for (int i = 0; i < 2; ++i) {
    r.lamp->location = r.lamp->location.getValue() + SbVec3f(0.1f, 0.0f, 0.0f);
    stats = r.frame();
  }
  EXPECT_EQ(r.messagesWith({"movingResolution", "using 0.125"}), 1);
  EXPECT_EQ(stats.tracerWidth, 30);  // 240 x 0.125
}

}  // namespace
}  // namespace ivshadow::test
