#include "image/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

using test::runOnTestDisplay;
using test::shareWithin;

// The viewer's screenshot (its own back buffer, read before the swap) against `ivshadow
// render` of the same file and size: the same Coin, the same nodes, drawn through GLX in the
// viewer and through EGL headlessly. DELAYED_BLEND is what the viewer's deep shadow scenes
// match (measured; plain Coin transparency in the viewer matches BLEND, see
// ViewerScenesTest.cpp); both scenes here are compared that way.
void expectViewerMatchesHeadless(const std::string& sceneName, double share) {
  const std::string dir = test::outputDir();
  const std::string shot = dir + "/viewer.png", headless = dir + "/headless.png";
  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", test::scenesDir() + "/" + sceneName, "-o", headless,
                 "--size", "320x240", "--transparency", "DELAYED_BLEND"});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  const Image b = readPng(headless);
  test::ProcessResult viewer;
  const Image a = test::viewerScreenshot({test::viewerExe(), "--screenshot", shot, "--size",
                                          "320x240", test::scenesDir() + "/" + sceneName},
                                         shot, b, share, viewer);
  ASSERT_EQ(viewer.exitCode, 0) << viewer.out << viewer.err;
  EXPECT_NE(viewer.out.find("wrote " + shot), std::string::npos) << viewer.out;
  ASSERT_EQ(a.width(), 320);
  ASSERT_EQ(a.height(), 240);
  // Not blank: the scene covers a good part of the view with non-black pixels.
  int lit = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      lit += a.pixel(x, y)[0] + a.pixel(x, y)[1] + a.pixel(x, y)[2] > 60 ? 1 : 0;
  EXPECT_GT(lit, 320 * 240 / 10) << "the screenshot is (nearly) blank: " << shot;
  EXPECT_GE(shareWithin(a, b, 2), share) << shot << " against " << headless;
}

TEST(ViewerSmoke, ScreenshotOfAnOpaqueSceneEqualsTheHeadlessRender) {
  // Same rasteriser, same state: every pixel agrees to within rounding.
  expectViewerMatchesHeadless("no_camera.iv", 0.999);
}

TEST(ViewerSmoke, ScreenshotShowsTheDeepShadowsOfTheHeadlessRender) {
  // The deep shadow group works in the viewer's GLX context as in EGL. Measured: 2 of 76,800
  // pixels differ (where transparent surfaces meet); 99.9 % leaves room for a few more.
  expectViewerMatchesHeadless("coloured_shadows.iv", 0.999);
}

TEST(ViewerSmoke, BadSceneInScreenshotModeExitsTwoWithoutScreenshot) {
  const std::string out = test::outputDir() + "/viewer.png";
  const test::ProcessResult result = runOnTestDisplay(
      {test::viewerExe(), "--screenshot", out, test::scenesDir() + "/malformed/unknown_node.iv"});
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find("unknown_node.iv:6: error:"), std::string::npos) << result.err;
  EXPECT_FALSE(test::fileExists(out));
}

TEST(ViewerSmoke, ViewWithoutDisplayExitsThreeWithAdvice) {
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "view", test::scenesDir() + "/no_camera.iv"}, {"DISPLAY="});
  EXPECT_EQ(result.exitCode, 3);
  EXPECT_NE(result.err.find("DISPLAY is not set"), std::string::npos) << result.err;
}

TEST(ViewerExamples, AnExistingSoQtApplicationRunsWithTheGroupAroundItsRoot) {
  const test::ProcessResult result =
      runOnTestDisplay({std::string(IVSHADOW_BIN_DIR) + "/soqt_add_shadows",
                        test::scenesDir() + "/glass_over_floor.iv", "--quit-after-ms", "1500"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(result.err.find("rror"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace ivshadow
