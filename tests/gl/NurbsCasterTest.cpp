#include "image_files/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace ivshadow {
namespace {

// The analytic picture of iv_scenes/nurbs_caster.iv at 400 x 400 (100 px per unit, the view
// x, y in -2..2): the floor lit by the light at (0, 0, 5), Lambert with no attenuation,
// 255 * 5 / |L - p|; the flat NURBS patch (diffuse 0.8) at z = 1 under the same light,
// 255 * 0.8 * 4 / |L - p|; black where the patch's shadow falls on the floor. Pixel centres
// within 1.5 px of an edge of the patch or the shadow are partly covered and not checked.
test::Expectation nurbsCasterPicture(int px, int py) {
  const double x = -2.0 + (px + 0.5) / 100.0, y = 2.0 - (py + 0.5) / 100.0;
  constexpr double kMargin = 0.015;
  const auto inside = [&](double x0, double x1, double y0, double y1) {
    return x > x0 + kMargin && x < x1 - kMargin && y > y0 + kMargin && y < y1 - kMargin;
  };
  const auto near = [&](double x0, double x1, double y0, double y1) {
    return x > x0 - kMargin && x < x1 + kMargin && y > y0 - kMargin && y < y1 + kMargin;
  };
  test::Expectation e;
  if (inside(0.5, 1.5, -0.5, 0.5)) {
    e.checked = true;
    const double distance = std::sqrt(x * x + y * y + 16.0);
    for (double& c : e.rgb) c = 255.0 * 0.8 * 4.0 / distance;
  } else if (near(0.5, 1.5, -0.5, 0.5)) {
    return e;
  } else if (inside(0.625, 1.875, -0.625, 0.625)) {
    e.checked = true;  // in the shadow: no ambient light, black
  } else if (!near(0.625, 1.875, -0.625, 0.625) && std::abs(x) < 2.0 - kMargin &&
             std::abs(y) < 2.0 - kMargin) {
    e.checked = true;
    const double distance = std::sqrt(x * x + y * y + 25.0);
    for (double& c : e.rgb) c = 255.0 * 5.0 / distance;
  }
  return e;
}

// Per-pixel lighting in single precision, rounded to 8 bits: one step.
constexpr double kTolerance = 1.0;

// A NURBS surface inside a group gives the casters' and the reference's SoCallbackAction its
// triangles only through an offscreen GL context, which Coin made with GLX and, without an X
// display, crashed on (SGI's teapot and glider samples). Headless runs now give Coin EGL
// contexts (headless/CoinOffscreenContexts.h): the patch is drawn and casts its shadow.
TEST(NurbsCaster, RenderShowsTheAnalyticShadowOfANurbsPatchWithEachMethod) {
  // GL's path with each of the light's methods, and the default (traced here).
  for (const std::string method : {"RAYS", "MAP", "default"}) {
    SCOPED_TRACE(method);
    const std::string out = test::outputDir() + "/" + method + ".png";
    std::vector<std::string> command = {test::ivshadowExe(),
                                        "render",
                                        test::scenesDir() + "/nurbs_caster.iv",
                                        "-o",
                                        out,
                                        "--size",
                                        "400x400"};
    if (method != "default")
      command.insert(command.end(),
                     {"--set", "Lamp.method=" + method, "--set", "Scene.renderer=RASTER"});
    const test::ProcessResult result = test::run(command);
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::string failure =
        test::compareWithExpectation(readPng(out), nurbsCasterPicture, kTolerance);
    EXPECT_TRUE(failure.empty()) << failure;
  }
}

TEST(NurbsCaster, ReferenceTracesTheNurbsPatch) {
  const std::string out = test::outputDir() + "/reference.png";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "reference", test::scenesDir() + "/nurbs_caster.iv", "-o",
                 out, "--size", "400x400"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string failure =
      test::compareWithExpectation(readPng(out), nurbsCasterPicture, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

}  // namespace
}  // namespace ivshadow
