#include "image_files/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <regex>

namespace ivshadow {
namespace {

using test::runOnTestDisplay;

struct Inspection {
  test::ProcessResult result;
  std::string picture;
};

Inspection inspect(const std::string& what) {
  const std::string dir = test::outputDir();
  Inspection run;
  run.picture = dir + "/map.png";
  run.result =
      runOnTestDisplay({test::viewerExe(), test::scenesDir() + "/coloured_shadows.iv", "--set",
                        "Scene.renderer=RASTER", "--set", "Lamp.resolution=256", "--set",
                        "Lamp.method=MAP", "--screenshot", dir + "/viewer.png", "--size", "160x120",
                        "--inspect", what, "--inspect-out", run.picture});
  return run;
}

// seeds/000 eq. 5.3, the SATURATE model the scene's light uses: the visibility after one
// surface of opacity a and colour c, as 8-bit steps.
std::array<int, 3> saturate(std::array<double, 3> colour, double transparency) {
  const double a = 1.0 - transparency;
  std::array<int, 3> out{};
  for (int i = 0; i < 3; ++i) {
    out[i] = int(std::lround(255.0 * (1.0 - a) * std::clamp(1.0 - a + colour[i], 0.0, 1.0)));
  }
  return out;
}

int texelsNear(const Image& image, const std::array<int, 3>& rgb, int tolerance) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      bool near = true;
      for (int c = 0; c < 3; ++c)
        near = near && std::abs(image.pixel(x, y)[c] - rgb[c]) <= tolerance;
      count += near ? 1 : 0;
    }
  return count;
}

TEST(ViewerInspector, FloorStraightBelowTheLightLiesAtTheLightsHeight) {
  const Inspection run = inspect("Lamp:-z:1");
  ASSERT_EQ(run.result.exitCode, 0) << run.result.err;
  // The centre texel of the -z face looks straight down from the light (z = 4.2) onto the
  // opaque floor (z = 0), with nothing in between (the panes and the sphere lie to the
  // side). The map stores the distance along the face axis, so every floor texel holds the
  // light's height whatever its direction: 4.2 up to float rounding (1e-3 allows for the
  // 32-bit distance and the printed 4 decimals). The floor is opaque: visibility 0.
  const std::regex centre(
      "centre texel: depth ([0-9.]+), visibility ([0-9.]+) ([0-9.]+) ([0-9.]+)");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(run.result.out, match, centre)) << run.result.out;
  EXPECT_NEAR(std::stod(match[1]), 4.2, 1e-3);
  for (int c = 2; c <= 4; ++c) EXPECT_EQ(std::stod(match[c]), 0.0) << run.result.out;
  const Image picture = readPng(run.picture);
  EXPECT_EQ(picture.width(), 256);
  EXPECT_EQ(picture.height(), 256);
}

TEST(ViewerInspector, FirstLayerShowsTheLightLeftAfterEachColouredPane) {
  const Inspection run = inspect("Lamp:-z:1:visibility");
  ASSERT_EQ(run.result.exitCode, 0) << run.result.err;
  const Image picture = readPng(run.picture);
  // Seen from the light, each pane is the first surface over a large patch of the -z face
  // (about 100 x 100 texels at this resolution), so that patch of layer 1 holds exactly the
  // visibility after that pane. 2 steps cover the rounding of the expected value and of the
  // inspector's 8-bit picture; 1,000 texels is a tenth of the smallest patch.
  EXPECT_GT(texelsNear(picture, saturate({0.95, 0.1, 0.1}, 0.5), 2), 1000) << "red pane";
  EXPECT_GT(texelsNear(picture, saturate({0.1, 0.9, 0.2}, 0.5), 2), 1000) << "green pane";
  EXPECT_GT(texelsNear(picture, saturate({0.15, 0.3, 1.0}, 0.5), 2), 1000) << "blue pane";
  // The opaque floor lets nothing through.
  EXPECT_GT(texelsNear(picture, {0, 0, 0}, 0), 10000) << "floor";
}

TEST(ViewerInspector, UnknownLightEmptyLayerAndBadSyntaxExitTwo) {
  struct Case {
    std::string inspect, message;
  };
  for (const Case& c : std::vector<Case>{
           {"Nope:-z:1", "no deep shadow light named 'Nope' has a map (lights: Lamp)"},
           {"Lamp:+z:1", "face +z holds 0 layers; layer 1 is empty"},
           {"Lamp:up:1", "expected LIGHT:FACE:LAYER"},
       }) {
    const Inspection run = inspect(c.inspect);
    EXPECT_EQ(run.result.exitCode, 2) << c.inspect << ": " << run.result.err;
    EXPECT_NE(run.result.err.find(c.message), std::string::npos) << run.result.err;
    EXPECT_FALSE(test::fileExists(run.picture)) << c.inspect;
    EXPECT_FALSE(test::fileExists(test::outputDir() + "/viewer.png")) << c.inspect;
  }
}

TEST(ViewerInspector, WithoutAMapItSaysWhatAutoChoseAndHowToSeeOne) {
  const std::string dir = test::outputDir();
  struct Case {
    std::vector<std::string> sets;
    std::vector<std::string> says;
  };
  // On llvmpipe the group left at renderer AUTO is traced on the CPU, and a light left at
  // method AUTO in a RASTER group traces shadow rays: neither keeps a map, and the inspector
  // says which choice did that and what to set instead (it asked "is its method RAYS?").
  for (const Case& c : std::vector<Case>{
           {{"Scene.renderer=AUTO", "Lamp.method=AUTO"},
            {"renderer AUTO, which chose TRACER", "set the group's renderer to RASTER",
             "method to MAP"}},
           {{"Scene.renderer=RASTER", "Lamp.method=AUTO"},
            {"method AUTO, which chose RAYS", "set its method to MAP"}},
       }) {
    std::vector<std::string> command = {
        test::viewerExe(), test::scenesDir() + "/coloured_shadows.iv",
        "--screenshot",    dir + "/viewer.png",
        "--size",          "160x120",
        "--inspect",       "Lamp:-z:1"};
    for (const std::string& set : c.sets) command.insert(command.end(), {"--set", set});
    const test::ProcessResult result = runOnTestDisplay(command);
    EXPECT_EQ(result.exitCode, 2) << result.err;
    for (const std::string& said : c.says)
      EXPECT_NE(result.err.find(said), std::string::npos) << said << " not in: " << result.err;
    EXPECT_EQ(result.err.find("is its method RAYS?"), std::string::npos) << result.err;
  }
}

}  // namespace
}  // namespace ivshadow
