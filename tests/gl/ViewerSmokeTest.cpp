#include "image_files/ImageFile.h"
#include "image_files/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>

namespace ivshadow {
namespace {

using test::runOnTestDisplay;
using test::shareWithin;

// The viewer's screenshot (its own back buffer, read before the swap) against `ivshadow
// render` of the same file and size: the same Coin, the same nodes, drawn through GLX in the
// viewer and through EGL headlessly, with the viewer's transparency type.
void expectViewerMatchesHeadless(const std::string& scene, double share) {
  const std::string dir = test::outputDir();
  const std::string shot = dir + "/viewer.png", headless = dir + "/headless.png";
  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", scene, "-o", headless, "--size", "320x240",
                 "--transparency", test::kViewerTransparency});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  const Image b = readPng(headless);
  test::ProcessResult viewer;
  const Image a = test::viewerScreenshot(
      {test::viewerExe(), "--screenshot", shot, "--size", "320x240", scene}, shot, viewer);
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
  expectViewerMatchesHeadless(test::scenesDir() + "/no_camera.iv", 0.999);
}

TEST(ViewerSmoke, ScreenshotShowsTheDeepShadowsOfTheHeadlessRender) {
  // The deep shadow group works in the viewer's GLX context as in EGL. Measured: 2 of 76,800
  // pixels differ (where transparent surfaces meet); 99.9 % leaves room for a few more.
  expectViewerMatchesHeadless(test::scenesDir() + "/coloured_shadows.iv", 0.999);
}

TEST(ViewerSmoke, PlainCoinGlassUnderAPointLightLooksAsInItsFirstFrame) {
  // No node of ours: Coin's own point light over transparent panes in front of a wall. The
  // screenshot is a frame after several unchanged ones; with Coin's render caches on, those
  // frames lit the panes differently from the first (3.8 % of the pixels up to 40 steps off,
  // docs/KNOWN_ISSUES.md), and `ivshadow render` draws a first frame. Measured with the
  // caches off: 2 of 76,800 pixels differ (where panes meet); 99.9 % leaves room for a few.
  const std::string scene = test::outputDir() + "/plain_glass.iv";
  std::ofstream(scene) << R"(#Inventor V2.1 ascii
Separator {
  PerspectiveCamera {
    position 0 -7.5 5.2 orientation 1 0 0 0.93 heightAngle 0.7 nearDistance 1 farDistance 30
  }
  PointLight { location 0.4 -0.6 4.2 intensity 0.95 }
  Separator {
    Material { diffuseColor 0.85 0.87 0.9 }
    Coordinate3 { point [ -4 3 0, 4 3 0, 4 3 4, -4 3 4 ] }
    FaceSet { numVertices 4 }
  }
  Separator {
    Transform { translation -0.3 0.2 1.9 rotation 1 0 0 0.35 }
    Coordinate3 { point [ -0.55 -0.7 0, 0.55 -0.7 0, 0.55 0.7 0, -0.55 0.7 0 ] }
    Separator {
      Material { diffuseColor 0.95 0.1 0.1 specularColor 0.6 0.6 0.6 shininess 0.8 transparency 0.5 }
      Translation { translation -0.9 0.3 0 }
      FaceSet { numVertices 4 }
    }
    Separator {
      Material { diffuseColor 0.1 0.9 0.2 specularColor 0.6 0.6 0.6 shininess 0.8 transparency 0.5 }
      Translation { translation 0.1 -0.35 0.25 }
      FaceSet { numVertices 4 }
    }
  }
}
)";
  expectViewerMatchesHeadless(scene, 0.999);
}

TEST(ViewerSmoke, BadSceneInScreenshotModeExitsTwoWithoutScreenshot) {
  const std::string out = test::outputDir() + "/viewer.png";
  const test::ProcessResult result = runOnTestDisplay(
      {test::viewerExe(), "--screenshot", out, test::scenesDir() + "/malformed/unknown_node.iv"});
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find("unknown_node.iv:6: error:"), std::string::npos) << result.err;
  EXPECT_FALSE(test::fileExists(out));
}

// `view --screenshot x.jpg` wrote PNG bytes under a .jpg name: the screenshot and the window
// follow their names' formats as `ivshadow render` does, and an output that cannot be
// written (the figures to /dev/full) takes the others with it.
TEST(ViewerSmoke, EveryPictureFollowsItsNamesFormatAndAFailedOutputLeavesNone) {
  const std::string dir = test::outputDir();
  const std::string shot = dir + "/shot.jpg", window = dir + "/window.JPEG";
  const std::string scene = test::scenesDir() + "/no_camera.iv";
  const test::ProcessResult result =
      runOnTestDisplay({test::ivshadowExe(), "view", scene, "--screenshot", shot, "--size",
                        "160x120", "--window-shot", window});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  for (const std::string& path : {shot, window})
    EXPECT_EQ(test::readText(path).substr(0, 3), std::string("\xFF\xD8\xFF", 3))
        << path << ": JPEG data, not PNG";
  const Image decoded = readImage(shot);
  EXPECT_EQ(decoded.width(), 160);
  EXPECT_EQ(decoded.height(), 120);

  const std::string lost = dir + "/lost.png";
  const test::ProcessResult failed =
      runOnTestDisplay({test::ivshadowExe(), "view", scene, "--screenshot", lost, "--size",
                        "160x120", "--figures", "/dev/full"});
  EXPECT_EQ(failed.exitCode, 1) << failed.err;
  EXPECT_NE(failed.err.find("/dev/full"), std::string::npos) << failed.err;
  EXPECT_FALSE(test::fileExists(lost));
  const test::ProcessResult bmp =
      runOnTestDisplay({test::ivshadowExe(), "view", scene, "--screenshot", dir + "/shot.bmp"});
  EXPECT_EQ(bmp.exitCode, 2);
  EXPECT_NE(bmp.err.find("cannot write images of type '.bmp'"), std::string::npos) << bmp.err;
}

TEST(ViewerSmoke, ViewWithoutDisplayExitsThreeWithAdvice) {
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "view", test::scenesDir() + "/no_camera.iv"}, {"DISPLAY="});
  EXPECT_EQ(result.exitCode, 3);
  EXPECT_NE(result.err.find("DISPLAY is not set"), std::string::npos) << result.err;
}

// Issue 35: a DISPLAY nobody answers aborted in Qt (exit 134). No server listens on display
// 97 (the tests' own server is elsewhere): the same advice, exit 3.
TEST(ViewerSmoke, ViewWithAnUnreachableDisplayExitsThreeWithAdvice) {
  const test::ProcessResult result = test::run(
      {test::ivshadowExe(), "view", test::scenesDir() + "/no_camera.iv"}, {"DISPLAY=:97"});
  EXPECT_EQ(result.exitCode, 3) << result.err;
  EXPECT_NE(result.err.find("cannot open the X display ':97'"), std::string::npos) << result.err;
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
