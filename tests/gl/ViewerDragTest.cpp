// `ivshadow-viewer --drag-light N`: the light dragger dragged as a user drags it, one step per
// frame. Over a group whose renderer is TRACER with movingResolution below 1 the frames of
// the drag are reduced, the group asks SoQt for the refined frame itself once the drag
// stops, and that frame is the full picture `ivshadow render` traces for the light's last
// place.
#include "image_files/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace ivshadow {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

struct Drag {
  test::ProcessResult result;
  Image shot;
  nlohmann::json figures;
};

Drag drag(const std::vector<std::string>& sets, int steps) {
  const std::string dir = test::outputDir();
  const std::string shot = dir + "/viewer.png", figures = dir + "/figures.json";
  std::vector<std::string> command = {
      test::viewerExe(), test::scenesDir() + "/coloured_shadows.iv",
      "--screenshot",    shot,
      "--figures",       figures,
      "--size",          std::to_string(kWidth) + "x" + std::to_string(kHeight),
      "--drag-light",    std::to_string(steps)};
  for (const std::string& set : sets) {
    command.push_back("--set");
    command.push_back(set);
  }
  Drag d;
  d.shot = test::viewerScreenshot(command, shot, d.result);
  const std::string text = test::readText(figures);
  if (!text.empty()) d.figures = nlohmann::json::parse(text);
  return d;
}

// The rows below the middle: the floor, its shadows and the panes, away from the dragger
// (drawn at the light, in the upper part of the picture).
Image lowerHalf(const Image& image) {
  Image part(kWidth, kHeight / 2);
  for (int y = 0; y < kHeight / 2; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 4; ++c) part.pixel(x, y)[c] = image.pixel(x, y + kHeight / 2)[c];
  return part;
}

TEST(ViewerDrag, ATracedGroupDraggedAtMovingResolutionRefinesToTheFullPicture) {
  const Drag d = drag({"Scene.renderer=TRACER", "Scene.movingResolution=0.5"}, 6);
  ASSERT_EQ(d.result.exitCode, 0) << d.result.err;
  ASSERT_TRUE(d.figures.contains("drag")) << "no drag figures";
  const nlohmann::json& figures = d.figures;
  EXPECT_EQ(figures["drag"]["frames"], 6);
  EXPECT_GT(figures["drag"]["frames_per_second"].get<double>(), 0.0);
  // Nothing moved after the drag: the refined frame came before the screenshot's, asked for
  // by the group.
  EXPECT_GE(figures["drag"]["frames_after"].get<int>(), 1);
  EXPECT_GE(figures["drag"]["refined_frames"].get<int>(), 1)
      << "the group did not ask for its refined frame";
  EXPECT_FALSE(figures["tracer_reduced"].get<bool>());
  EXPECT_EQ(figures["tracer_size"], nlohmann::json::array({kWidth, kHeight}));

  // The headless trace for the light's last place: the same picture (2 steps, 99.9 %, as the
  // other viewer comparisons: the viewer's automatic near and far planes round depths apart).
  const nlohmann::json& where = figures["drag"]["light_location"];
  char location[128];
  std::snprintf(location, sizeof location, "Lamp.location=%.9g %.9g %.9g", where[0].get<double>(),
                where[1].get<double>(), where[2].get<double>());
  const std::string headless = test::outputDir() + "/headless.png";
  const test::ProcessResult render = test::run(
      {test::ivshadowExe(), "render", test::scenesDir() + "/coloured_shadows.iv", "-o", headless,
       "--size", std::to_string(kWidth) + "x" + std::to_string(kHeight), "--transparency",
       test::kViewerTransparency, "--set", "Scene.renderer=TRACER", "--set", location});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  test::expectMostlyEqual(lowerHalf(d.shot), lowerHalf(readPng(headless)), 2, 0.999,
                          "the still picture after the drag against the headless trace");
}

// At full resolution there is nothing to refine. (Frames after the drag are not counted: the
// X server may ask the window to redraw, under load.)
TEST(ViewerDrag, AFullResolutionGroupHasNothingToRefine) {
  // movingResolution 1 pinned: its default traces reduced frames while the light moves.
  const Drag d = drag({"Scene.renderer=TRACER", "Scene.movingResolution=1"}, 4);
  ASSERT_EQ(d.result.exitCode, 0) << d.result.err;
  ASSERT_TRUE(d.figures.contains("drag")) << "no drag figures";
  EXPECT_EQ(d.figures["drag"]["frames"], 4);
  EXPECT_EQ(d.figures["drag"]["refined_frames"], 0);
  EXPECT_EQ(d.figures["tracer_refines"], 0);
  EXPECT_FALSE(d.figures["tracer_reduced"].get<bool>());
}

TEST(ViewerDrag, NeedsAScreenshotAndADeepShadowLight) {
  const std::string shot = test::outputDir() + "/none.png";
  test::ProcessResult result = test::runOnTestDisplay(
      {test::viewerExe(), test::scenesDir() + "/coloured_shadows.iv", "--drag-light", "3"});
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("--drag-light need"), std::string::npos) << result.err;

  result = test::runOnTestDisplay({test::viewerExe(), test::scenesDir() + "/lit_plane.iv",
                                   "--screenshot", shot, "--drag-light", "3"});
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("no DeepShadowLight"), std::string::npos) << result.err;
  EXPECT_FALSE(test::fileExists(shot)) << "a failed drag left a screenshot";
}

}  // namespace
}  // namespace ivshadow
