// The exact CPU renderer against the analytic pictures the GL tests use: the reference must
// be right on its own before it can judge the GL path.
#include "raytrace/ReferenceRenderer.h"
#include "scene/ViewSetup.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace ivshadow::test
