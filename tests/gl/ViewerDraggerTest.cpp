#include "image_files/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ivshadow {
namespace {

using test::runOnTestDisplay;

Image screenshot(const std::string& name, bool dragger) {
  const std::string path = test::outputDir() + "/" + name;
  const std::string scene = test::scenesDir() + "/coloured_shadows.iv";
  std::vector<std::string> command = {test::viewerExe(), scene,    "--screenshot", path,
                                      "--size",          "320x240"};
  for (const char* set : {"Lamp.method=MAP", "Lamp.resolution=256", "Lamp.location=0.4 -0.6 2.5"}) {
    command.push_back("--set");
    command.push_back(set);
  }
  if (dragger) command.push_back("--light-dragger");
  const test::ProcessResult result = runOnTestDisplay(command);
  EXPECT_EQ(result.exitCode, 0) << result.err;
  return readPng(path);
}

TEST(ViewerDragger, DraggerSitsOnTheLightAndCastsNoShadow) {
  const Image without = screenshot("without.png", false);
  const Image with = screenshot("with.png", true);

  // Where the light is on screen, from the scene's camera (position 0 -7.5 5.2, rotated
  // 0.93 rad about x, heightAngle 0.7, 4:3): the light at (0.4, -0.6, 2.5) lies 7.145 units
  // along the view direction, 1.961 above and 0.4 right of the view axis, which projects to
  // pixel (178, 30).
  const double angle = 0.93, tanHalf = std::tan(0.35);
  const double dy = -0.6 + 7.5, dz = 2.5 - 5.2;
  const double depth = dy * std::sin(angle) - dz * std::cos(angle);
  const double up = dy * std::cos(angle) + dz * std::sin(angle);
  const int px = int(std::lround((1.0 + 0.4 / depth / (tanHalf * 320.0 / 240.0)) * 160.0));
  const int py = int(std::lround((1.0 - up / depth / tanHalf) * 120.0));
  ASSERT_NEAR(px, 178, 1);
  ASSERT_NEAR(py, 30, 1);
  // The dragger's ball, about 0.3 units across there (4 % of the scene's 8-unit size), covers
  // the 5 x 5 pixels around that point: most of them change, by more than 10 steps.
  int changed = 0;
  for (int y = py - 2; y <= py + 2; ++y)
    for (int x = px - 2; x <= px + 2; ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(with.pixel(x, y)[c] - without.pixel(x, y)[c]));
      changed += worst > 10 ? 1 : 0;
    }
  EXPECT_GE(changed, 20) << "no dragger at the light's position";

  // Outside the shadow group the dragger casts nothing: the floor in the lower half of the
  // picture, left of the glass sphere (x < 200), is unchanged but for rounding (same 2-step,
  // 99.9 % tolerance as the other viewer comparisons).
  Image floorWith(200, 90), floorWithout(200, 90);
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 200; ++x)
      for (int c = 0; c < 4; ++c) {
        floorWith.pixel(x, y)[c] = with.pixel(x, y + 150)[c];
        floorWithout.pixel(x, y)[c] = without.pixel(x, y + 150)[c];
      }
  test::expectMostlyEqual(floorWith, floorWithout, 2, 0.999, "floor with and without dragger");
}

// The three numbers after `field` that follows `node` in an Inventor file's text.
std::vector<float> vectorAfter(const std::string& text, const std::string& node,
                               const std::string& field) {
  const std::size_t at = text.find(field + " ", text.find(node));
  if (at == std::string::npos) return {};
  std::istringstream in(text.substr(at + field.size()));
  std::vector<float> values(3);
  in >> values[0] >> values[1] >> values[2];
  return values;
}

TEST(ViewerDragger, ADraggerOutsideTheViewIsBroughtIntoIt) {
  // coloured_shadows.iv's lamp hangs above the top edge of the file's view (it projects to
  // 1.49 half-heights above the centre), where its dragger could be neither seen nor grabbed.
  const std::string dir = test::outputDir();
  const std::string scene = test::scenesDir() + "/coloured_shadows.iv";
  const test::ProcessResult viewer =
      runOnTestDisplay({test::viewerExe(), scene, "--light-dragger", "--screenshot",
                        dir + "/with.png", "--save-scene", dir + "/saved.iv", "--size", "320x240",
                        "--set", "Scene.renderer=RASTER", "--set", "Lamp.method=MAP"});
  ASSERT_EQ(viewer.exitCode, 0) << viewer.err;
  // The camera moved back, not the light: the saved scene keeps the lamp where it was.
  const std::string saved = test::readText(dir + "/saved.iv");
  EXPECT_EQ(vectorAfter(saved, "DEF Lamp", "location"), std::vector<float>({0.4f, -0.6f, 4.2f}))
      << saved;
  const std::vector<float> camera = vectorAfter(saved, "PerspectiveCamera", "position");
  ASSERT_EQ(camera.size(), 3u) << "no camera position in the saved scene: " << saved;
  EXPECT_NE(camera, std::vector<float>({0.0f, -7.5f, 5.2f}))
      << "the camera did not move: " << saved;
  // The saved scene (the moved camera, no dragger) rendered headlessly is the viewer's picture
  // but for the dragger, which shows as a patch of changed pixels inside the picture. Without
  // it in view the two agreed everywhere.
  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", dir + "/saved.iv", "-o", dir + "/without.png",
                 "--size", "320x240", "--transparency", test::kViewerTransparency});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  const Image with = readPng(dir + "/with.png"), without = readPng(dir + "/without.png");
  int changed = 0;
  for (int y = 0; y < with.height(); ++y)
    for (int x = 0; x < with.width(); ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(with.pixel(x, y)[c] - without.pixel(x, y)[c]));
      changed += worst > 10 ? 1 : 0;
    }
  // The dragger is some 0.3 units across at about 10 units' distance: 20 pixels at least; and
  // it is all that differs (under 2 % of the picture).
  EXPECT_GE(changed, 20) << "no dragger in the picture";
  EXPECT_LT(changed, 320 * 240 / 50) << "more than the dragger differs";
}

}  // namespace
}  // namespace ivshadow
