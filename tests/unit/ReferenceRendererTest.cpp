// The exact CPU renderer against the analytic pictures the GL tests use: the reference must
// be right on its own before it can judge the GL path.
#include "reference/ReferenceRenderer.h"
#include "scene_input/ViewSetup.h"
#include "tests/gl/ShadowScene.h"
#include "tests/support/BounceWall.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoSeparator.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ivshadow::test {
namespace {

// Per-pixel float shading rounded once to 8 bits: half a step of rounding plus float error
// far below a step. One step bounds it (the same bound as the GL tests).
constexpr double kTolerance = 1.0;

void expectPicture(const ShadowScene& scene, const ShadowPicture& picture) {
  const std::string failure =
      compareWithExpectation(referenceIv(scene.text(), ShadowScene::kSize), picture, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The reference of each analytic case (ShadowScene.h) gives its picture within one step.
class ReferenceAnalytic : public ::testing::TestWithParam<AnalyticCase> {};

TEST_P(ReferenceAnalytic, MatchesThePicture) {
  expectPicture(GetParam().scene, GetParam().picture());
}

INSTANTIATE_TEST_SUITE_P(Cases, ReferenceAnalytic, ::testing::ValuesIn(analyticCases()),
                         analyticCaseName);

TEST(ReferenceRenderer, StackedFiltersMultiplyWhateverMaxLayersSays) {
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  // The reference has no layer limit: every surface counts.
  scene.lightFields = "maxLayers 1";
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(ReferenceRenderer, AlphaTexturedCheckerboard) {
  ShadowScene scene;
  const Filter checker = checkerboardFilter();
  scene.filters = {checker};
  const Image image = referenceIv(scene.text(), ShadowScene::kSize);
  expectCheckerboardShadow(image, kTolerance);
}

TEST(ReferenceRenderer, ShadowStyleDecidesWhoCastsAndWhoReceives) {
  ShadowScene noCast;
  Filter glass = kRedGlass;
  glass.nodes = "ShadowStyle { style SHADOWED }";
  noCast.filters = {glass};
  ShadowScene expected;  // a glass that casts nothing looks like a fully clear one's floor
  Filter clear = kRedGlass;
  clear.transparency = 1.0;
  expected.filters = {clear};
  const Image image = referenceIv(noCast.text(), ShadowScene::kSize);
  ShadowPicture picture{&expected, ColourModel::Saturate};
  const std::string failure = compareWithExpectation(
      image,
      [&](int x, int y) {
        // The glass itself is seen (not clear) in the middle: check only the floor around it.
        Expectation e = picture(x, y);
        const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
        if (std::max(std::abs(px), std::abs(py)) < 0.3 + 0.02) e.checked = false;
        return e;
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(ReferenceRenderer, LinesAndPointsAreNamedAsNotDrawn) {
  SoSeparator* root = readIv(
      "#Inventor V2.1 ascii\nSeparator { DEF Wire LineSet { vertexProperty VertexProperty { "
      "vertex [ 0 0 0, 1 1 0 ] } numVertices 2 } }");
  const ViewSetup view = ViewSetup::prepare(root, SbViewportRegion(32, 32));
  ReferenceOptions options;
  options.width = options.height = 32;
  const std::optional<ReferenceResult> result = renderReference(view.root.get(), options);
  root->unref();
  ASSERT_TRUE(result.has_value());
  ASSERT_EQ(result->warnings.size(), 1u);
  EXPECT_NE(result->warnings[0].find("LineSet 'Wire'"), std::string::npos) << result->warnings[0];
}

TEST(ReferenceBounce, FormFactorOfTheKnownCases) {
  // A point on the axis of a disc-like large square: the form factor tends to 1 for a huge
  // square right above; half of an infinite half-plane's view: 1/2. The square of the scene
  // (bounce_wall.iv) from the wall's centre: 0.31755, the closed form for two perpendicular
  // rectangles (1 / 2 pi) (atan(1 / Y) - Y / sqrt(X^2 + Y^2) atan(1 / sqrt(X^2 + Y^2))) with
  // X = 2, Y = 0.5, for each half of the floor.
  const glm::dvec3 up(0, 0, 1);
  EXPECT_NEAR(formFactor({0, 0, 0}, up, {{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}}),
              1.0, 1e-3);
  const double X = 2.0, Y = 0.5, pi = std::acos(-1.0);
  const double half =
      (std::atan(1.0 / Y) - Y / std::hypot(X, Y) * std::atan(1.0 / std::hypot(X, Y))) / (2.0 * pi);
  EXPECT_NEAR(formFactor({0, 0, 0.5}, {1, 0, 0}, {{0, -1, 0}, {2, -1, 0}, {2, 1, 0}, {0, 1, 0}}),
              2.0 * half, 1e-9);
  EXPECT_NEAR(2.0 * half, 0.31755, 1e-5);
}

ReferenceResult bounceWall(int size, int samples) {
  std::ifstream file(scenesDir() + "/bounce_wall.iv");
  std::stringstream text;
  text << file.rdbuf();
  SoSeparator* root = readIv(text.str());
  const ViewSetup view = ViewSetup::prepare(root, SbViewportRegion(short(size), short(size)));
  ReferenceOptions options;
  options.width = options.height = size;
  options.bounceSamples = samples;
  std::optional<ReferenceResult> result = renderReference(view.root.get(), options);
  root->unref();
  if (!result) throw std::runtime_error("the reference render was cancelled");
  return *result;
}

TEST(ReferenceBounce, WithoutItTheWallGetsNoLight) {
  // Parallel to the light, no ambient: without the bounce the wall is black to the bit.
  const ReferenceResult result = bounceWall(32, 0);
  EXPECT_EQ(result.bounceRays, 0u);
  for (int py = 0; py < 32; ++py)
    for (int px = 0; px < 32; ++px) {
      const glm::dvec3 p = bounceWallPoint(px, py, 32);
      if (std::abs(p.y) > 0.9 || p.z < 0.1 || p.z > 0.9) continue;
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(result.image.rgb[(std::size_t(py) * 32 + std::size_t(px)) * 3 + std::size_t(c)], 0.0f);
    }
}

TEST(ReferenceBounce, TheWallShowsTheFloorsTintedLightTimesTheFormFactor) {
  // The floor's radiance is the pane's transmittance T = (0.5, 0.25, 0.25) (SATURATE: (1 - a)
  // clamp(1 - a + c), kd 1, I 1, straight down); the wall's is kd T F, F the form factor from
  // its point to the floor (nothing but the floor lies below the pane: rays upwards pass the
  // glass and meet nothing).
  constexpr int kSize = 64;
  const ReferenceResult result = bounceWall(kSize, 1024);
  EXPECT_GT(result.bounceRays, 0u);
  const std::array<double, 3>& through = kBounceWallTransmittance;
  const std::vector<glm::dvec3> floor = bounceWallFloor();
  std::array<double, 3> sum{}, expectedSum{};
  int pixels = 0;
  double worst = 0.0, squares = 0.0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const glm::dvec3 p = bounceWallPoint(px, py, kSize);
      if (!inBounceWallPatch(p)) continue;
      const double f = formFactor(p, {1, 0, 0}, floor);
      ++pixels;
      for (std::size_t c = 0; c < 3; ++c) {
        const double actual =
            result.image.rgb[(std::size_t(py) * kSize + std::size_t(px)) * 3 + c];
        const double expected = through[c] * f;
        sum[c] += actual;
        expectedSum[c] += expected;
        const double relative = (actual - expected) / expected;
        worst = std::max(worst, std::abs(relative));
        if (c == 0) squares += relative * relative;
      }
    }
  ASSERT_GT(pixels, 100);
  // Each point's estimate is a mean over 32 x 32 strata of whether the ray meets the floor;
  // only the strata the floor's edge crosses vary, which leaves a per-pixel relative error of
  // 3.3 % RMS (measured; 5.9 % at 256 rays, so it falls about as 1 / sqrt(rays)). Bounds: the
  // RMS below 5 %, every pixel within 20 % (6 of those), and the patch's 160 pixels on
  // average within 1.5 % (6 times the 0.26 % a mean of 160 such errors would spread by).
  // A cosine left out, a normal not of unit length or a missed tint is off by 30 % or more.
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(sum[c] / expectedSum[c], 1.0, 0.015) << "channel " << c;
  EXPECT_LT(std::sqrt(squares / pixels), 0.05);
  EXPECT_LT(worst, 0.20);
  // The tint: red twice green, as through the glass.
  EXPECT_NEAR(sum[0] / sum[1], 2.0, 1e-4);
}

}  // namespace
}  // namespace ivshadow::test
