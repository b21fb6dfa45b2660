#include "image/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <set>

namespace ivshadow {
namespace {

// The viewer needs an X display; the tests give it a private Xvfb server (Mesa's GLX draws
// with llvmpipe there).
test::ProcessResult runUnderXvfb(const std::vector<std::string>& arguments) {
  std::vector<std::string> command = {"xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"};
  command.insert(command.end(), arguments.begin(), arguments.end());
  return test::run(command);
}

TEST(ViewerSmoke, LoadsASceneAndSavesANonBlankScreenshot) {
  const std::string out = test::outputDir() + "/viewer.png";
  const test::ProcessResult result = runUnderXvfb({test::viewerExe(), "--screenshot", out, "--size",
                                                   "320x240", test::scenesDir() + "/no_camera.iv"});
  ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
  const Image image = readPng(out);
  ASSERT_EQ(image.width(), 320);
  ASSERT_EQ(image.height(), 240);
  // Not blank: the two shapes cover a good part of the picture in several colours.
  int lit = 0;
  std::set<int> hues;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] + p[1] + p[2] < 30) continue;
      ++lit;
      hues.insert((p[0] > p[2] ? 1 : 0) | (p[2] > p[0] ? 2 : 0));
    }
  }
  EXPECT_GT(lit, image.width() * image.height() / 20);
  EXPECT_EQ(hues.size(), 2u) << "expected the blue cube and the orange sphere";
}

TEST(ViewerSmoke, BadSceneInScreenshotModeExitsTwoWithoutScreenshot) {
  const std::string out = test::outputDir() + "/viewer.png";
  const test::ProcessResult result = runUnderXvfb(
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

}  // namespace
}  // namespace ivshadow
