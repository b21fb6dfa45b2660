#include "image_files/ImageComparison.h"
#include "image_files/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/CoinMessageCapture.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace ivshadow {
namespace {

// Every scene of the library: it loads without a message from Coin, renders, shows
// something, builds its deep shadow map once with the layers its casters need, and with the
// RAYS method builds its casters' BVH and traces once.
struct LibraryScene {
  const char* file;
  int minimumLayersOnSomeFace;  // the deepest stack of surfaces any face must hold
  bool allSixFaces;             // casters all around the light
};

class SceneLibrary : public ::testing::TestWithParam<LibraryScene> {};

constexpr int kCloseSteps = 8;
constexpr double kCloseShare = 0.9;

void setMethod(SoNode* root, int method) {
  SoSearchAction search;
  search.setType(SoDeepShadowLight::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength(); ++i)
    static_cast<SoDeepShadowLight*>(search.getPaths()[i]->getTail())->method = method;
}

// Two frames without a message from Coin, and a picture that is not mostly black.
void renderTwiceQuietly(test::CheckedRenderer& renderer, SoNode* root) {
  {
    CoinMessageCapture capture;
    renderer.render(root);
    renderer.render(root);
    // Only the default renderer's one note of what AUTO chose.
    for (const auto& message : capture.messages())
      if (message.raw.find("renderer AUTO uses") == std::string::npos) ADD_FAILURE() << message.raw;
  }
  const Image image = renderer.read();
  int lit = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      lit += image.pixel(x, y)[0] + image.pixel(x, y)[1] + image.pixel(x, y)[2] > 30 ? 1 : 0;
  EXPECT_GT(lit, image.width() * image.height() / 5) << "mostly black";
}

TEST_P(SceneLibrary, RendersWithItsShadows) {
  const LibraryScene& scene = GetParam();
  init();
  constexpr int kWidth = 160, kHeight = 120;
  std::string error;
  auto renderer = test::CheckedRenderer::create(kWidth, kHeight, error);
  ASSERT_TRUE(renderer) << error;
  LoadedScene loaded = loadScene(test::scenesDir() + "/" + scene.file);
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  const ViewSetup view = ViewSetup::prepare(loaded.root.get(), SbViewportRegion(kWidth, kHeight));

  // The default first (AUTO: traced on this software rasteriser), then GL's maps and rays.
  renderTwiceQuietly(*renderer, view.root.get());
  test::setOnEveryGroup(view.root.get(), "renderer RASTER");
  setMethod(view.root.get(), SoDeepShadowLight::MAP);
  renderTwiceQuietly(*renderer, view.root.get());
  const Image mapped = renderer->read();
  DeepShadowStatistics stats = collectDeepShadowStatistics(view.root.get());
  ASSERT_EQ(stats.lights.size(), 1u);
  EXPECT_EQ(stats.rebuilds, 1) << "two frames of an unchanged scene build the map once";
  const auto& faces = stats.lights[0].layersUsed;
  EXPECT_GE(*std::max_element(faces.begin(), faces.end()), scene.minimumLayersOnSomeFace);
  if (scene.allSixFaces)
    for (int used : faces) EXPECT_GE(used, 2) << "a panel and a wall on every face";

  setMethod(view.root.get(), SoDeepShadowLight::RAYS);
  renderTwiceQuietly(*renderer, view.root.get());
  stats = collectDeepShadowStatistics(view.root.get());
  ASSERT_EQ(stats.lights.size(), 1u);
  EXPECT_EQ(stats.lights[0].method, "RAYS");
  EXPECT_EQ(stats.bvhBuilds, 1);
  EXPECT_EQ(stats.rayFrames, 1) << "two frames of an unchanged scene trace once";
  EXPECT_GT(stats.raysTraced, 0u);
  // The same shadows, exact: the pictures differ only where the map is coarse (shadow edges,
  // up to a texel wide) or cut off (surfaces beyond its layers), which is a small share.
  const Image traced = renderer->read();
  int close = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(traced.pixel(x, y)[c] - mapped.pixel(x, y)[c]));
      close += worst <= kCloseSteps ? 1 : 0;
    }
  EXPECT_GE(double(close) / (kWidth * kHeight), kCloseShare)
      << "the traced shadows are not the map's";
}

INSTANTIATE_TEST_SUITE_P(
    Bundled, SceneLibrary,
    ::testing::Values(
        LibraryScene{"chapel.iv", 2, false}, LibraryScene{"bottles.iv", 3, false},
        // Leaves are opaque or clear texel by texel: one layer holds them all.
        LibraryScene{"foliage.iv", 1, false},
        // Three window screens and the floor behind them.
        LibraryScene{"atrium.iv", 4, false}, LibraryScene{"all_directions.iv", 2, true},
        LibraryScene{"coloured_shadows.iv", 2, false}, LibraryScene{"peeled_glasses.iv", 2, false},
        LibraryScene{"stress_100k.iv", 3, false}, LibraryScene{"stress_1m.iv", 3, false}),
    [](const ::testing::TestParamInfo<LibraryScene>& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(SceneLibraryVariants, TheChapelVariantsRender) {
  const std::string dir = test::outputDir() + "/chapel";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/chapel.iv",
                 test::scenesDir() + "/chapel.variants", "-o", dir, "--size", "96x72", "--frames",
                 "1", "--jobs", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("rendered 5 of 5 variants"), std::string::npos) << result.out;
  EXPECT_TRUE(test::fileExists(dir + "/index.html"));
}

TEST(SceneLibraryVariants, TheDemoVariantsRender) {
  const std::string dir = test::outputDir() + "/demo";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv",
                 test::scenesDir() + "/coloured_shadows.variants", "-o", dir, "--size", "96x72",
                 "--frames", "1", "--jobs", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("rendered 10 of 10 variants"), std::string::npos) << result.out;
  // Each varies what acts on the path it renders by: no two pictures are the same, and no
  // setting said it did nothing.
  EXPECT_EQ(result.err.find("does nothing"), std::string::npos) << result.err;
  std::vector<std::pair<std::string, Image>> pictures;
  for (const std::string& file : test::filesIn(dir))
    if (file.size() > 4 && file.compare(file.size() - 4, 4, ".png") == 0)
      pictures.emplace_back(file, readPng(dir + "/" + file));
  ASSERT_EQ(pictures.size(), 10u);
  for (std::size_t i = 0; i < pictures.size(); ++i)
    for (std::size_t j = i + 1; j < pictures.size(); ++j)
      EXPECT_GT(
          ImageComparison::compare(pictures[i].second, pictures[j].second, "a", "b").all.maxError,
          0)
          << pictures[i].first << " and " << pictures[j].first << " are the same picture";
}

}  // namespace
}  // namespace ivshadow
