#include "image_files/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace ivshadow {
namespace {

using test::readText;
using test::runOnTestDisplay;

int occurrences(const std::string& text, const std::string& word) {
  int count = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
    ++count;
  return count;
}

// Pixels whose channels are all at least 250: white, where a light saturates the floor.
int saturated(const Image& image) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      count += std::min({p[0], p[1], p[2]}) >= 250 ? 1 : 0;
    }
  return count;
}

struct AddedShadows {
  test::ProcessResult run;
  std::string saved;
  Image picture;
};

// The viewer's "Add shadows" on a bundled scene: the saved result and the picture.
AddedShadows addShadows(const std::string& sceneName) {
  const std::string dir = test::outputDir();
  AddedShadows added;
  added.run = runOnTestDisplay({test::viewerExe(), test::scenesDir() + "/" + sceneName,
                                "--add-light", "--save-scene", dir + "/added.iv", "--screenshot",
                                dir + "/viewer.png", "--size", "320x240"});
  added.saved = readText(dir + "/added.iv");
  if (added.run.exitCode == 0) added.picture = readPng(dir + "/viewer.png");
  return added;
}

// The scene the viewer saved in `dir` (added.iv) rendered headlessly with its group inactive:
// the same lights, camera and ground, no shadows. Empty when the render failed (said).
Image unshadowedRender(const std::string& dir) {
  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", dir + "/added.iv", "-o", dir + "/unshadowed.png",
                 "--size", "320x240", "--transparency", test::kViewerTransparency, "--set",
                 "ShadowGroup.isActive=FALSE"});
  EXPECT_EQ(render.exitCode, 0) << render.err;
  return render.exitCode == 0 ? readPng(dir + "/unshadowed.png") : Image();
}

TEST(ViewerAddShadows, TheLampOfGlassOverFloorCastsTheGlasssRedShadowInsteadOfASecondLight) {
  const AddedShadows added = addShadows("glass_over_floor.iv");
  ASSERT_EQ(added.run.exitCode, 0) << added.run.err;
  // The scene's point light casts, as it is: one light, as in the file, not the file's and a
  // new one.
  EXPECT_EQ(occurrences(added.saved, "DeepShadowLight"), 0) << added.saved;
  EXPECT_EQ(occurrences(added.saved, "DEF Lamp PointLight"), 1) << added.saved;
  EXPECT_EQ(occurrences(added.saved, "DEF ShadowGroup TransparentShadowGroup"), 1) << added.saved;

  // Independent of the viewer's code: the file edited by hand as a user would, everything
  // after the camera put in a shadow group, rendered headlessly with the viewer's
  // transparency type.
  const std::string dir = test::outputDir();
  std::string text = readText(test::scenesDir() + "/glass_over_floor.iv");
  const std::string lamp = "DEF Lamp PointLight {";
  ASSERT_NE(text.find(lamp), std::string::npos);
  text.replace(text.find(lamp), lamp.size(), "TransparentShadowGroup {\n  " + lamp);
  text.replace(text.rfind('}'), 1, "}\n}");
  std::ofstream(dir + "/by_hand.iv") << text;
  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", dir + "/by_hand.iv", "-o", dir + "/by_hand.png",
                 "--size", "320x240", "--transparency", test::kViewerTransparency});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  // Same tolerance as the other viewer-against-render comparisons of deep shadow scenes.
  test::expectMostlyEqual(added.picture, readPng(dir + "/by_hand.png"), 2, 0.999,
                          "viewer after Add shadows against the hand-made equivalent");

  // The camera looks at the floor's centre, straight below the lamp (distance 2, Lambert
  // factor 1) and in the glass's shadow: light through alpha 0.5 red glass is, by seeds/000
  // eq. 5.3 (colorModel SATURATE), (1 - a) clamp(1 - a + c) = 0.5 red, 0.25 green and blue
  // of white: (128, 64, 64). 4 steps: 8-bit rounding and Coin's per-vertex lighting, whose
  // neighbouring vertices 0.125 away see the lamp at cos 0.998.
  const std::uint8_t* centre = added.picture.pixel(160, 120);
  EXPECT_NEAR(centre[0], 128, 4);
  EXPECT_NEAR(centre[1], 64, 4);
  EXPECT_NEAR(centre[2], 64, 4);
  // Nothing is over-lit: the floor is brightest just outside the shadow (radius 1 below a
  // lamp 2 high, Lambert factor 2 / sqrt(5) = 0.89, 228). Two lights saturated it to white.
  EXPECT_EQ(saturated(added.picture), 0) << "white pixels: the floor is lit twice";
}

TEST(ViewerAddShadows, ASceneWithoutLightsGetsOneWhoseShadowIsSeen) {
  // glass_over_floor.iv without its lamp (no_camera.iv, the bundled scene without lights, has
  // nothing for a shadow to fall on; ViewerPanel.AddLight... covers it).
  const std::string dir = test::outputDir();
  std::string text = readText(test::scenesDir() + "/glass_over_floor.iv");
  const std::size_t lamp = text.find("DEF Lamp PointLight {");
  ASSERT_NE(lamp, std::string::npos);
  text.erase(lamp, text.find('}', lamp) + 1 - lamp);
  std::ofstream(dir + "/unlit.iv") << text;
  const test::ProcessResult viewer = runOnTestDisplay(
      {test::viewerExe(), dir + "/unlit.iv", "--add-light", "--save-scene", dir + "/added.iv",
       "--screenshot", dir + "/viewer.png", "--size", "320x240"});
  ASSERT_EQ(viewer.exitCode, 0) << viewer.err;
  const std::string saved = readText(dir + "/added.iv");
  EXPECT_EQ(occurrences(saved, "DeepShadowLight"), 1) << saved;
  EXPECT_NE(saved.find("DEF ShadowLight DeepShadowLight"), std::string::npos) << saved;

  // Against the saved scene rendered with the group inactive (the same light, no shadows):
  // the glass's shadow on the floor is where the picture is darker and red rather than
  // white: by seeds/000 eq. 5.3 the alpha 0.5 red glass lets through 50 % of red and 25 % of
  // green and blue. Counted: pixels whose green and blue drop by more than 20 steps while red
  // keeps more than 35 % and exceeds green by 20 (a coloured shadow, not rounding); at least
  // 1 % of the picture (the shadow covers some 4 %).
  const Image unshadowed = unshadowedRender(dir);
  ASSERT_GT(unshadowed.width(), 0);
  const Image picture = readPng(dir + "/viewer.png");
  int tinted = 0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) {
      const std::uint8_t* lit = unshadowed.pixel(x, y);
      const std::uint8_t* shown = picture.pixel(x, y);
      tinted += lit[1] - shown[1] > 20 && lit[2] - shown[2] > 20 && shown[0] > 0.35 * lit[0] &&
                        shown[0] > shown[1] + 20
                    ? 1
                    : 0;
    }
  EXPECT_GT(tinted, 320 * 240 / 100) << "no red shadow to be seen";
}

TEST(ViewerAddShadows, SpotAndDirectionalLightsCastAsTheyAre) {
  const AddedShadows added = addShadows("shading_features.iv");
  ASSERT_EQ(added.run.exitCode, 0) << added.run.err;
  // The scene's point, spot and directional lights are kept as they are, all on, inside the
  // group, where they cast: no light is added, none is replaced or switched off.
  EXPECT_EQ(occurrences(added.saved, "DeepShadowLight"), 0) << added.saved;
  EXPECT_EQ(occurrences(added.saved, "PointLight"), 1) << added.saved;
  EXPECT_EQ(occurrences(added.saved, "SpotLight"), 1) << added.saved;
  EXPECT_EQ(occurrences(added.saved, "DirectionalLight"), 1) << added.saved;
  EXPECT_EQ(occurrences(added.saved, "on FALSE"), 0) << added.saved;
  const std::size_t group = added.saved.find("TransparentShadowGroup");
  ASSERT_NE(group, std::string::npos) << added.saved;
  EXPECT_LT(group, added.saved.find("SpotLight")) << added.saved;
  EXPECT_LT(group, added.saved.find("DirectionalLight")) << added.saved;
}

TEST(ViewerAddShadows, AModelWithoutAFloorGetsAGroundThatCatchesItsShadow) {
  // chess/king.iv (Debian's inventor-data) is a chess piece alone: wrapped, it cast its shadow
  // into the void, and the lamp above lit one side, the rest black.
  const std::string king = "/usr/share/inventor/data/models/chess/king.iv";
  if (!test::fileExists(king)) GTEST_SKIP() << king << " is not installed (inventor-data)";
  const std::string dir = test::outputDir();
  const test::ProcessResult viewer = runOnTestDisplay(
      {test::viewerExe(), king, "--add-light", "--add-ground", "--save-scene", dir + "/added.iv",
       "--screenshot", dir + "/viewer.png", "--size", "320x240"});
  ASSERT_EQ(viewer.exitCode, 0) << viewer.err;
  const std::string saved = readText(dir + "/added.iv");
  EXPECT_NE(saved.find("DEF ShadowGround Separator"), std::string::npos) << saved;
  EXPECT_NE(saved.find("DEF ShadowFill DirectionalLight"), std::string::npos) << saved;
  EXPECT_EQ(occurrences(saved, "DeepShadowLight"), 1) << saved;

  // Against the saved scene with its group inactive (the same lights, ground and camera, no
  // shadows): the shadow is where the ground is darker, by more than 40 steps, on at least 2 %
  // of the picture; and the fill light lights the side the lamp does not reach, so that a
  // fifth of the picture is more than dark (without the ground and the fill, 9 %).
  const Image unshadowed = unshadowedRender(dir);
  ASSERT_GT(unshadowed.width(), 0);
  const Image picture = readPng(dir + "/viewer.png");
  int darker = 0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) {
      const std::uint8_t* lit = unshadowed.pixel(x, y);
      const std::uint8_t* shown = picture.pixel(x, y);
      darker += lit[0] - shown[0] > 40 && lit[1] - shown[1] > 40 && lit[2] - shown[2] > 40 ? 1 : 0;
    }
  EXPECT_GT(darker, 320 * 240 / 50) << "no shadow on the ground";
  EXPECT_GT(test::shareLit(picture), 0.2) << "the picture is mostly black";
}

}  // namespace
}  // namespace ivshadow
