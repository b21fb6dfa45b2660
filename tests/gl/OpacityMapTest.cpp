// SoDeepShadowLight's OPACITY_MAP method (after seeds/002): exact where every receiver lies at
// least one slice behind each transparent caster (the analytic catalogue with 32 slices), the
// documented partial absorption nearer than that, computed here from the geometry and the
// slice count alone, opaque casters as sharp as in a shadow map whatever the slices, and a
// cost fixed by the slices, not by the layers a scene has.
#include "headless/OffscreenRenderer.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene/CoinMessageCapture.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ivshadow::test {
namespace {

// Per-pixel float shading; the absorption summed in 32-bit floats, its exp rounded once to
// 8 bits: one step bounds it, the 1/255.
constexpr double kTolerance = 1.0;

ShadowScene withOpacityMap(ShadowScene scene, int slices) {
  scene.method = "OPACITY_MAP";
  scene.lightFields += " slices " + std::to_string(slices);
  return scene;
}

void expectPicture(const ShadowScene& scene, const ExpectedImage& picture) {
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  const std::string failure = compareWithExpectation(image, picture, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The catalogue's light is 1 above the floor and its filters at heights 0.5 and 0.25: the
// fitted range along the light's axes (the casters' nearest axial distance, 0.5, to the
// farthest corner, 1.75) in 32 slices is 0.04 a slice, while the nearest receiver lies 0.25
// behind the filter above it (at least 0.14 along a face's axis when the content is turned
// into a cube corner): every filter counts fully, and the map is exact.
class OpacityMapAnalytic : public ::testing::TestWithParam<AnalyticCase> {};

TEST_P(OpacityMapAnalytic, MatchesThePictureWithEnoughSlices) {
  expectPicture(withOpacityMap(GetParam().scene, 32), GetParam().picture());
}

INSTANTIATE_TEST_SUITE_P(Cases, OpacityMapAnalytic, ::testing::ValuesIn(analyticCases()),
                         analyticCaseName);

// The picture seeds/002's interpolation gives a floor 0.25 behind the red glass (both seen
// along the -z face's axis: glass at distance 0.5, floor at 1) with the slices spread over
// the distances 0.1 .. 2.1: in slice coordinates the glass is at 0.2 and the floor at 0.45,
// so the glass's absorption counts min((0.45 - 0.2) N, 1) = min(N / 4, 1) times. The floor
// receives the exact shadow's transmittance T to that power: lit * (exact / lit)^w, per
// channel.
TEST(OpacityMap, AReceiverNearerThanASliceGetsThatShareOfTheAbsorption) {
  for (const int slices : {1, 2, 3, 4, 8}) {
    ShadowScene scene;
    scene.filters = {kRedGlass};
    scene.lightFields = "nearRadius 0.1 farRadius 2.1";
    scene = withOpacityMap(scene, slices);
    const double weight = std::min(0.25 * slices, 1.0);
    ShadowScene unfiltered = scene;
    unfiltered.filters[0].transparency = 1.0;  // the lit floor, where the glass is seen too
    const ShadowPicture exact{&scene, ColourModel::Saturate};
    const ShadowPicture lit{&unfiltered, ColourModel::Saturate};
    const auto picture = [&](int x, int y) {
      Expectation e = exact(x, y);
      const Expectation open = lit(x, y);
      if (!e.checked || !open.checked) return Expectation{};
      for (std::size_t c = 0; c < 3; ++c)
        if (open.rgb[c] > 0.0) e.rgb[c] = open.rgb[c] * std::pow(e.rgb[c] / open.rgb[c], weight);
      return e;
    };
    SCOPED_TRACE("slices " + std::to_string(slices));
    expectPicture(scene, picture);
  }
}

TEST(OpacityMap, AnOpaqueCasterShadowsSharplyWithOneSlice) {
  // The opaque square and the floor share the one slice; its shadow is the opaque depth's,
  // as a shadow map's, and the glass's partial absorption is not spread over it.
  ShadowScene scene;
  Filter blocker = kRedGlass;
  blocker.transparency = 0.0;
  scene.filters = {blocker};
  scene = withOpacityMap(scene, 1);
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(OpacityMap, HalfPrecisionKeepsThePicture) {
  // 16-bit absorption (relative error 5e-4) and slice coordinates (the glass's 0.2 within
  // 1e-4): a tenth of a step.
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightFields = "precision HALF";
  scene = withOpacityMap(scene, 32);
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(OpacityMap, CostIsTheSlicesNotTheLayersOfTheScene) {
  // Eight panes stacked 0.05 apart between the light and the floor: a deep shadow map peels a
  // layer a pane; the opacity map draws each face once per kOpacitySlicesPerDraw (7) slices,
  // so 1 draw for 4 slices and 5 for 32, and keeps 4 bytes of opaque depth plus 16 per slice
  // per texel. 32 slices over the fitted 0.49 .. 1.75 are 0.04 apart: every pane lies in a
  // slice of its own before the floor, which sees all eight exactly.
  ShadowScene scene;
  for (int i = 0; i < 8; ++i) {
    Filter pane = kGreenGlass;
    pane.halfSize = 0.2;
    pane.height = 0.5 - 0.05 * i;
    pane.transparency = 0.2;
    scene.filters.push_back(pane);
  }
  for (const int slices : {4, 32}) {
    const ShadowScene sliced = withOpacityMap(scene, slices);
    SoNode* root = nullptr;
    const Image image = renderIv(sliced.text(), ShadowScene::kSize, &root);
    const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
    root->unref();
    ASSERT_EQ(stats.lights.size(), 1u);
    const DeepShadowLightStatistics& light = stats.lights[0];
    EXPECT_EQ(light.method, "OPACITY_MAP");
    const int draws = (slices + 6) / 7;
    for (int face = 0; face < 6; ++face) {
      EXPECT_EQ(light.passes[std::size_t(face)], draws) << "face " << face;
      EXPECT_EQ(light.layersUsed[std::size_t(face)], slices) << "face " << face;
    }
    const std::uint64_t texels = std::uint64_t(light.resolution) * std::uint64_t(light.resolution);
    EXPECT_EQ(light.bytes, texels * 6u * (4u + 16u * std::uint64_t(slices)));
    if (slices == 32) {
      const std::string failure = compareWithExpectation(
          image, ShadowPicture{&sliced, ColourModel::Saturate}, kTolerance);
      EXPECT_TRUE(failure.empty()) << failure;
    }
  }
}

TEST(OpacityMap, OutOfRangeSlicesAreClampedWithOneWarning) {
  init();
  for (const auto& [asked, used] : {std::pair{0, 1}, std::pair{99, 32}}) {
    ShadowScene scene;
    scene.filters = {kRedGlass};
    scene = withOpacityMap(scene, asked);
    SoSeparator* root = readIv(scene.text());
    auto* lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
    ASSERT_NE(lamp, nullptr);
    std::string error;
    auto renderer = OffscreenRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
    ASSERT_TRUE(renderer) << error;
    std::vector<std::string> warnings;
    {
      CoinMessageCapture capture;
      renderer->render(root);
      lamp->touch();  // forces a rebuild, which resolves the fields again
      renderer->render(root);
      for (const auto& message : capture.messages())
        if (message.raw.find("SoDeepShadowLight") != std::string::npos)
          warnings.push_back(message.raw);
    }
    const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
    renderer.reset();
    root->unref();
    EXPECT_EQ(stats.rebuilds, 2);
    ASSERT_EQ(stats.lights.size(), 1u);
    EXPECT_EQ(stats.lights[0].layersUsed[0], used);
    ASSERT_EQ(warnings.size(), 1u) << "slices " << asked << ": one warning, although built twice";
    const std::string expected = "\"Lamp\": field slices is " + std::to_string(asked) +
                                 ", outside 1..32; using " + std::to_string(used);
    EXPECT_NE(warnings[0].find(expected), std::string::npos) << warnings[0];
  }
}

}  // namespace
}  // namespace ivshadow::test
