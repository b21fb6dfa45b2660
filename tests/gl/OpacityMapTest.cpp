// SoDeepShadowLight's OPACITY_MAP method (after seeds/002): exact where every receiver lies at
// least one slice behind each transparent caster (the analytic catalogue with 32 slices), the
// documented partial absorption nearer than that, computed here from the geometry and the
// slice count alone, opaque casters as sharp as in a shadow map whatever the slices, and a
// cost fixed by the slices, not by the layers a scene has.
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>

#include <epoxy/gl.h>
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
// slices divide the transparent filters' distances along the cube's axes (0.5 to 0.75 along
// -z for the stacked pair), and the floor lies beyond them all, a quarter of the distance or
// more behind the nearest filter (at least 0.14 along a face's axis when the content is
// turned into a cube corner): every filter counts fully, and the map is exact. 32 slices, so
// that the filters within one case are also in slices of their own.
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

TEST(OpacityMap, AFloorBeyondEveryPaneCountsThemAllWithOneSlice) {
  // The slices span the transparent casters only (0.5 to 0.75 from the light along -z), not
  // the opaque floor they shadow: the floor lies past their one slice and takes both filters
  // whole. Had the slice spanned the floor too (to 1 and beyond), the floor would lie within
  // it and get about half their absorption.
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene = withOpacityMap(scene, 1);
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(OpacityMap, AnOpaqueCasterShadowsSharplyWithOneSlice) {
  // An opaque square 0.1 above the floor, lit along (1, 0, -1): its shadow is the square moved
  // 0.1 along x, seen beside it where 0.3 < x < 0.4. With no transparent caster the one slice
  // spans the map's depth along the light, about 1.5, so the floor lies a tenth of it behind
  // the square: had the square's absorption, -log 2^-24, gone into the slice, the floor there
  // would get exp(-0.1 x 16.6) of the light, 0.2, 36 steps. The opaque depth gives it none.
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
      "  TransparentShadowGroup {\n"
      "    method OPACITY_MAP slices 1\n"
      "    DirectionalLight { direction 1 0 -1 }\n"
      "    Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
      "    Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }\n"
      "    QuadMesh { verticesPerRow 2 verticesPerColumn 2 }\n"
      "    Coordinate3 { point [ -0.3 -0.3 0.1, 0.3 -0.3 0.1, 0.3 0.3 0.1, -0.3 0.3 0.1 ] }\n"
      "    FaceSet { numVertices 4 }\n  }\n}\n";
  const Image image = renderIv(text, ShadowScene::kSize);
  const std::string failure = compareWithExpectation(
      image,
      [](int px, int py) {
        Expectation e;
        const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
        // Two pixels off every edge: the square's, its shadow's, the floor's.
        const bool square = std::max(std::abs(x), std::abs(y)) < 0.32;
        const bool shadow = std::max(std::abs(x - 0.1), std::abs(y)) < 0.32;
        const bool clearOfEdges = std::max(std::abs(x - 0.1), std::abs(y)) < 0.28 ||
                                  std::max(std::abs(x - 0.1), std::abs(y)) > 0.32;
        if (square || !clearOfEdges || std::max(std::abs(x), std::abs(y)) > 0.98) return e;
        e.checked = true;
        e.rgb.fill(shadow ? 0.0 : 255.0 / std::sqrt(2.0));  // Lambert: cos 45 degrees
        return e;
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(OpacityMap, HalfPrecisionKeepsThePicture) {
  // 16-bit running sums of absorption (relative error 5e-4 of at most 2.8 here) and slice
  // coordinates (within 5e-4 of a slice 0.016 deep, two slices or more from the floor's): a
  // tenth of a step.
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightFields = "precision HALF";
  scene = withOpacityMap(scene, 32);
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(OpacityMap, CostIsTheSlicesNotTheLayersOfTheScene) {
  // One pane, then eight stacked 0.05 apart between the light and the floor: a deep shadow
  // map peels a layer a pane; the opacity map draws each face once per kOpacitySlicesPerDraw
  // (7) slices whatever the panes, so 1 draw for 4 slices and 5 for 32, and keeps 4 bytes of
  // opaque depth plus 16 per slice per texel. The floor lies beyond the panes, the last of
  // their slices: it sees all eight exactly.
  for (const int panes : {1, 8}) {
    ShadowScene scene;
    for (int i = 0; i < panes; ++i) {
      Filter pane = kGreenGlass;
      pane.halfSize = 0.2;
      pane.height = 0.5 - 0.05 * i;
      pane.transparency = 0.2;
      scene.filters.push_back(pane);
    }
    for (const int slices : {4, 32}) {
      SCOPED_TRACE(std::to_string(panes) + " panes, " + std::to_string(slices) + " slices");
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
      const std::uint64_t texels =
          std::uint64_t(light.resolution) * std::uint64_t(light.resolution);
      EXPECT_EQ(light.bytes, texels * 6u * (4u + 16u * std::uint64_t(slices)));
      if (slices == 32) {
        const std::string failure = compareWithExpectation(
            image, ShadowPicture{&sliced, ColourModel::Saturate}, kTolerance);
        EXPECT_TRUE(failure.empty()) << failure;
      }
    }
  }
}

TEST(OpacityMap, SharesAGroupWithADeepShadowMapAndSwitchesAtRunTime) {
  // Two lights at one place, half the intensity each (ShadowScene::lightCount): with both
  // exact for these filters, any mix of MAP and OPACITY_MAP gives the one analytic picture,
  // and each slot keeps the map of its method only. The frame with both is the one whose
  // shading compiles both lookups and picks per light.
  init();
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightCount = 2;
  scene.lightFields = "slices 32";
  SoSeparator* root = readIv(scene.text());
  auto* first = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  auto* second = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp1"));
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  const ShadowPicture picture{&scene, ColourModel::Saturate};
  const int methods[][2] = {{SoDeepShadowLight::MAP, SoDeepShadowLight::OPACITY_MAP},
                            {SoDeepShadowLight::OPACITY_MAP, SoDeepShadowLight::OPACITY_MAP},
                            {SoDeepShadowLight::OPACITY_MAP, SoDeepShadowLight::MAP},
                            {SoDeepShadowLight::RAYS, SoDeepShadowLight::OPACITY_MAP}};
  for (const auto& pair : methods) {
    first->method = pair[0];
    second->method = pair[1];
    renderer->render(root);
    SCOPED_TRACE("methods " + std::to_string(pair[0]) + ", " + std::to_string(pair[1]));
    const std::string failure = compareWithExpectation(renderer->read(), picture, kTolerance);
    EXPECT_TRUE(failure.empty()) << failure;
    const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
    ASSERT_EQ(stats.lights.size(), 2u);
    for (int i = 0; i < 2; ++i) {
      const DeepShadowLightStatistics& light = stats.lights[std::size_t(i)];
      const std::uint64_t texels =
          std::uint64_t(light.resolution) * std::uint64_t(light.resolution);
      if (pair[i] == SoDeepShadowLight::OPACITY_MAP) {
        EXPECT_EQ(light.method, "OPACITY_MAP");
        EXPECT_EQ(light.bytes, texels * 6u * (4u + 16u * 32u));
      } else if (pair[i] == SoDeepShadowLight::MAP) {
        // Two filters and the floor seen through the -z face; no more than that kept.
        EXPECT_EQ(light.method, "MAP");
        EXPECT_LT(light.bytes, texels * 6u * (4u + 16u * 32u) / 10u);
      } else {
        EXPECT_EQ(light.bytes, 0u);
      }
    }
  }
  // Seven colour attachments blended by their own equations in the build: none is left so
  // for Coin, which sets the blend equation for all of them at once.
  GLint equation0 = 0;
  glGetIntegeri_v(GL_BLEND_EQUATION_RGB, 0, &equation0);
  for (GLuint i = 1; i <= 7; ++i) {
    GLint rgb = 0, alpha = 0;
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, i, &rgb);
    glGetIntegeri_v(GL_BLEND_EQUATION_ALPHA, i, &alpha);
    EXPECT_EQ(rgb, equation0) << "draw buffer " << i;
    EXPECT_EQ(alpha, equation0) << "draw buffer " << i;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  renderer.reset();
  root->unref();
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
    auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
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
