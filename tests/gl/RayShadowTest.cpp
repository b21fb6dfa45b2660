// SoDeepShadowLight's RAYS method (and, where they hold for both, VOLUMES): the deep shadow
// tests' analytic pictures, now with no layer, resolution or bias error to allow for; AUTO's
// choice; what is traced again and when.
#include "image_files/ImageComparison.h"
#include "image_files/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTranslation.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <tuple>

namespace ivshadow::test {
namespace {

// Per-pixel float shading and a float transmittance stored as a 16-bit float (relative error
// 1e-3, a quarter step at most) rounded once to 8 bits: one step bounds it, the issue's
// 1/255.
constexpr double kTolerance = 1.0;

ShadowScene withRays(ShadowScene scene) {
  scene.method = "RAYS";
  return scene;
}

// The two methods that shadow the surfaces the camera sees, with no map: traced rays and
// shadow volumes. Both are exact, so the tests below hold for both alike.
const char* const kScreenMethods[] = {"RAYS", "VOLUMES"};

std::string methodParamName(const std::string& method) {
  return method == "RAYS" ? "Rays" : "Volumes";
}

void expectPicture(const ShadowScene& scene, const ShadowPicture& picture) {
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  const std::string failure = compareWithExpectation(image, picture, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The traced shadows and the shadow volumes of each analytic case (ShadowScene.h) give its
// picture within one step (for the volumes: sums of log transmittance in 32-bit floats, their
// exp stored in 16 bits, the same bound).
class ScreenShadowsAnalytic
    : public ::testing::TestWithParam<std::tuple<AnalyticCase, const char*>> {};

TEST_P(ScreenShadowsAnalytic, MatchesThePicture) {
  ShadowScene scene = std::get<0>(GetParam()).scene;
  scene.method = std::get<1>(GetParam());
  expectPicture(scene, std::get<0>(GetParam()).picture());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ScreenShadowsAnalytic,
    ::testing::Combine(::testing::ValuesIn(analyticCases()), ::testing::ValuesIn(kScreenMethods)),
    [](const ::testing::TestParamInfo<std::tuple<AnalyticCase, const char*>>& info) {
      return std::get<0>(info.param).name + methodParamName(std::get<1>(info.param));
    });

class ScreenShadows : public ::testing::TestWithParam<const char*> {
 protected:
  ShadowScene withMethod(ShadowScene scene) const {
    scene.method = GetParam();
    return scene;
  }
};

INSTANTIATE_TEST_SUITE_P(Methods, ScreenShadows, ::testing::ValuesIn(kScreenMethods),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return methodParamName(info.param);
                         });

TEST_P(ScreenShadows, EverySurfaceCountsWhateverMaxLayersSays) {
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightFields = "maxLayers 1";
  scene = withMethod(scene);
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(RayShadows, AlphaTexturedCheckerboardIsSampledInTheFilter) {
  ShadowScene scene;
  const Filter checker = checkerboardFilter();
  scene.filters = {checker};
  scene = withRays(scene);
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  expectCheckerboardShadow(image, kTolerance);
}

TEST(RayShadows, GrazingLightDoesNotShadowTheReceiverItself) {
  // The light 1e-3 above the floor's plane, far to one side: every floor point sees it at a
  // grazing angle, where an offset too small would let the floor shadow itself. Nothing is
  // between, so the floor is the plain Lambert picture of that light.
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
      "  TransparentShadowGroup { renderer RASTER\n"
      "    DeepShadowLight { location -3 0 0.001 method RAYS }\n"
      "    Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
      "    Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }\n"
      "    QuadMesh { verticesPerRow 2 verticesPerColumn 2 }\n  }\n}\n";
  const Image image = renderIv(text, ShadowScene::kSize);
  const std::string failure = compareWithExpectation(
      image,
      [](int x, int y) {
        Expectation e;
        const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
        if (std::max(std::abs(px), std::abs(py)) > 0.98) return e;
        const double dx = -3.0 - px, dy = -py, dz = 0.001;
        const double cosine = dz / std::sqrt(dx * dx + dy * dy + dz * dz);
        e.checked = true;
        e.rgb.fill(255.0 * cosine);
        return e;
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(RayShadows, TheFirstFrameBuildsOneBvhTracesOnceAndKeepsNoMap) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene = withRays(scene);
  SoNode* root = nullptr;
  renderIv(scene.text(), ShadowScene::kSize, &root);
  DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  ASSERT_EQ(stats.lights.size(), 1u);
  EXPECT_EQ(stats.lights[0].method, "RAYS");
  EXPECT_EQ(stats.lights[0].bytes, 0u);  // no map is kept
  EXPECT_EQ(stats.bvhBuilds, 1);
  EXPECT_EQ(stats.rayFrames, 1);
  EXPECT_GT(stats.bvhBytes, 0u);
  // One ray per floor and filter pixel seen: the floor covers 200 x 200 pixels.
  EXPECT_GE(stats.raysTraced, 200u * 200u);
  root->unref();
}

TEST(RayShadows, StaticFramesReuseTheTraceAMovedLightIsTracedAgainOnly) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene = withRays(scene);
  SoSeparator* root = readIv(scene.text());  // initialises Coin and the plugin first
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  for (int i = 0; i < 3; ++i) renderer->render(root);
  DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  EXPECT_EQ(stats.rayFrames, 1);  // nothing moved: traced once
  EXPECT_EQ(stats.bvhBuilds, 1);

  auto* lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  ASSERT_NE(lamp, nullptr);
  lamp->location.setValue(0.1f, 0.0f, 1.0f);
  renderer->render(root);
  stats = collectDeepShadowStatistics(root);
  EXPECT_EQ(stats.rayFrames, 2);  // the light moved: traced again
  EXPECT_EQ(stats.bvhBuilds, 1);  // but the casters did not change

  SoSearchAction search;
  search.setType(SoMaterial::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(SoNode::getByName("Filter0"));
  ASSERT_GT(search.getPaths().getLength(), 0);
  static_cast<SoMaterial*>(search.getPaths()[0]->getTail())->transparency.setValue(0.25f);
  renderer->render(root);
  stats = collectDeepShadowStatistics(root);
  EXPECT_EQ(stats.bvhBuilds, 1);  // a caster's colour changed: the same tree holds
  EXPECT_EQ(stats.bvhRefits, 0);
  EXPECT_EQ(stats.rayFrames, 3);

  // A caster moved: its triangles keep their order, so the tree is refitted, not rebuilt.
  auto* filter = static_cast<SoSeparator*>(SoNode::getByName("Filter0"));
  ASSERT_NE(filter, nullptr);
  auto* move = new SoTranslation;
  move->translation.setValue(0.0f, 0.0f, 0.1f);
  filter->insertChild(move, 0);
  renderer->render(root);
  stats = collectDeepShadowStatistics(root);
  EXPECT_EQ(stats.rayFrames, 4);
  EXPECT_EQ(stats.bvhBuilds, 1);
  EXPECT_EQ(stats.bvhRefits, 1);
  // The refitted tree casts the moved glass's shadow. From the light at (0.1, 0, 1) the
  // glass's right edge (x 0.3) fell on the floor at x 0.5 from height 0.5, and falls at 0.6
  // from height 0.6: the floor point (0.555, 0) is in the new shadow only.
  const Image image = renderer->read();
  const int px = 175, py = 120;
  // Lambert's cosine from the moved light, 1 above (0.1, 0).
  const double x = -1.2 + (px + 0.5) / 100.0 - 0.1, y = 1.2 - (py + 0.5) / 100.0;
  const double lambert = 255.0 / std::sqrt(1.0 + x * x + y * y);
  // Opacity a = 0.75 now: (1 - a) clamp(1 - a + c) is 0.25 for red, 0.0625 for green.
  EXPECT_NEAR(image.pixel(px, py)[0], lambert * 0.25, kTolerance);
  EXPECT_NEAR(image.pixel(px, py)[1], lambert * 0.0625, kTolerance);
  root->unref();
}

TEST_P(ScreenShadows, ACameraInsideTheGroupMovedIsTracedAgain) {
  // The group is traversed before a camera inside it: only the camera's notification can
  // tell the group that the traced shadows no longer fit the view, and the volumes must be
  // drawn with the view that camera sets, not the one above the group (none here).
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene = withMethod(scene);
  std::string text = scene.text();
  const std::string camera =
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n";
  ASSERT_NE(text.find(camera), std::string::npos);
  text.erase(text.find(camera), camera.size());
  // After the group's fields, before its first child.
  const std::string group = "renderer RASTER\n";
  text.insert(text.find(group) + group.size(),
              "    DEF Eye OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 "
              "height 2.4 }\n");
  SoSeparator* root = readIv(text);
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  renderer->render(root);
  EXPECT_EQ(collectDeepShadowStatistics(root).rayFrames, 1);
  ShadowPicture picture{&scene, ColourModel::Saturate};
  const std::string before = compareWithExpectation(renderer->read(), picture, kTolerance);
  EXPECT_TRUE(before.empty()) << before;
  auto* eye = static_cast<SoCamera*>(SoNode::getByName("Eye"));
  ASSERT_NE(eye, nullptr);
  eye->position.setValue(0.3f, 0.0f, 5.0f);
  renderer->render(root);
  EXPECT_EQ(collectDeepShadowStatistics(root).rayFrames, 2);
  // The picture is the moved view's: the analytic floor shifted by 30 pixels.
  const Image image = renderer->read();
  root->unref();
  const std::string failure = compareWithExpectation(
      image, [&](int x, int y) { return picture(x + 30, y); }, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(RayShadows, LightsOfBothMethodsShareAGroup) {
  // Two lights at one place, half the intensity each: one keeps a map, one traces. Their sum
  // is the single light's analytic picture.
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightCount = 2;
  std::string text = scene.text();
  const std::string second = "DEF Lamp1 DeepShadowLight { location 0 0 1 intensity 0.5 method MAP";
  ASSERT_NE(text.find(second), std::string::npos) << text;
  text.replace(text.find(second), second.size(),
               "DEF Lamp1 DeepShadowLight { location 0 0 1 intensity 0.5 method RAYS");
  SoNode* root = nullptr;
  const Image image = renderIv(text, ShadowScene::kSize, &root);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  root->unref();
  ASSERT_EQ(stats.lights.size(), 2u);
  EXPECT_EQ(stats.lights[0].method, "MAP");
  EXPECT_EQ(stats.lights[1].method, "RAYS");
  const std::string failure =
      compareWithExpectation(image, ShadowPicture{&scene, ColourModel::Saturate}, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(RayShadows, LinesCastNothingAndAreNamedOnce) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene.floorNodes = "";
  std::string text = scene.text();
  // A wire between light and floor, in the group: neither method can cast from it.
  text.insert(text.rfind("  }\n}"),
              "    DEF Wire LineSet { vertexProperty VertexProperty { vertex [ -0.5 0 0.6, 0.5 0 "
              "0.6 ] } numVertices 2 }\n");
  init();  // Coin's initialisation installs its own handlers: capture after it
  CoinMessageCapture capture;
  SoNode* root = nullptr;
  renderIv(text, ShadowScene::kSize, &root);
  renderIv(text, ShadowScene::kSize);
  root->unref();
  std::size_t named = 0;
  for (const auto& message : capture.messages())
    if (message.raw.find("LineSet 'Wire'") != std::string::npos) ++named;
  EXPECT_EQ(named, 1u);
}

std::string sceneFile(const std::string& name) {
  return scenesDir() + "/" + name;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(RayShadows, AutoTracesRaysOnThisSoftwareRendererAndSaysSo) {
  const std::string dir = outputDir();
  const ProcessResult result =
      run({ivshadowExe(), "render", sceneFile("coloured_shadows.iv"), "-o", dir + "/a.png",
           "--size", "160x120", "--frames", "2", "--stats", dir + "/stats.json", "--set",
           "Scene.renderer=RASTER"});  // the light's AUTO acts on GL's path
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json stats = readJson(dir + "/stats.json");
  const std::string renderer = stats.at("gl_renderer");
  ASSERT_NE(renderer.find("llvmpipe"), std::string::npos) << "this test expects Mesa llvmpipe";
  EXPECT_EQ(stats.at("passes").at("shadow_method"), "RAYS");
  EXPECT_EQ(stats.at("dsm_layers_used").at(0).at("method"), "RAYS");
  EXPECT_GT(stats.at("passes").at("rays_ms").get<double>(), 0.0);
  EXPECT_GT(stats.at("passes").at("rays_capture_gpu_ms").get<double>(), 0.0);
  EXPECT_GE(stats.at("passes").at("rays_ms").get<double>(),
            stats.at("passes").at("rays_capture_ms").get<double>() +
                stats.at("passes").at("rays_trace_ms").get<double>());
  EXPECT_GT(stats.at("ray_layers").get<int>(), 1);  // the floor and the glass in front of it
  EXPECT_EQ(stats.at("bvh_builds").get<int>(), 1);
  EXPECT_GT(stats.at("rays_traced").get<std::uint64_t>(), 0u);
  EXPECT_GT(stats.at("bvh_bytes").get<std::uint64_t>(), 0u);
  EXPECT_EQ(stats.at("ray_frames").get<int>(), 1);  // the second frame reused the trace
  // The choice is logged once, naming the light and the renderer.
  std::size_t logged = 0;
  for (const std::string& line : lines(result.err))
    if (line.find("'Lamp': method AUTO uses RAYS") != std::string::npos) ++logged;
  EXPECT_EQ(logged, 1u) << result.err;
}

TEST(RayShadows, WithoutRoomForTheCastersTheLightWarnsOnceAndKeepsAMap) {
  const std::string dir = outputDir();
  const ProcessResult result =
      run({ivshadowExe(), "render", sceneFile("coloured_shadows.iv"), "-o", dir + "/a.png",
           "--size", "160x120", "--frames", "2", "--stats", dir + "/stats.json", "--set",
           "Lamp.method=RAYS", "--set", "Scene.renderer=RASTER"},
          {"IVSHADOW_EMBREE_MEMORY_LIMIT=1000"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json stats = readJson(dir + "/stats.json");
  EXPECT_EQ(stats.at("passes").at("shadow_method"), "MAP");
  std::size_t warned = 0;
  for (const std::string& line : lines(result.err))
    if (line.find("'Lamp': cannot trace shadow rays") != std::string::npos) ++warned;
  EXPECT_EQ(warned, 1u) << result.err;
  // The map's picture: the MAP method rendered on purpose gives the same one.
  const ProcessResult map = run({ivshadowExe(), "render", sceneFile("coloured_shadows.iv"), "-o",
                                 dir + "/map.png", "--size", "160x120", "--frames", "2", "--set",
                                 "Lamp.method=MAP", "--set", "Scene.renderer=RASTER"});
  ASSERT_EQ(map.exitCode, 0) << map.err;
  const Image fallback = readPng(dir + "/a.png"), expected = readPng(dir + "/map.png");
  const std::string failure = compareWithExpectation(
      fallback,
      [&](int x, int y) {
        Expectation e;
        e.checked = true;
        for (int c = 0; c < 3; ++c) e.rgb[std::size_t(c)] = expected.pixel(x, y)[c];
        return e;
      },
      0.0);
  EXPECT_TRUE(failure.empty()) << failure;
}

// Scenes whose camera view has no transparency Coin blends out of order and whose casters
// have one colour per face (so the volumes are exact too): there the only difference from
// the exact reference left is rasterisation against a ray through the pixel centre on
// silhouettes, and 16-bit visibility (a quarter step): at least 50 dB at 640 x 480.
class ScreenReferenceAgreement
    : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(ScreenReferenceAgreement, AtLeastFiftyDecibels) {
  const std::string param = std::get<0>(GetParam());  // "scene.iv:Group:Light"
  const std::string name = param.substr(0, param.find(':'));
  const std::string rest = param.substr(param.find(':') + 1);
  const std::string group = rest.substr(0, rest.find(':'));
  const std::string light = rest.substr(rest.find(':') + 1);
  // GL's path, whose screen methods these are (the default, AUTO, traces on a software
  // rasteriser with the reference's own code).
  const ImageComparison metrics = renderAgainstReference(
      sceneFile(name), "640x480",
      {"--set", light + ".method=" + std::get<1>(GetParam()), "--set", group + ".renderer=RASTER"},
      50.0);
  EXPECT_GE(metrics.all.psnr, 50.0) << "actual, reference and diff.png in " << outputDir();
}

INSTANTIATE_TEST_SUITE_P(
    BundledScenes, ScreenReferenceAgreement,
    ::testing::Combine(::testing::Values("chapel.iv:Chapel:Sun", "all_directions.iv:Room:Lamp",
                                         "atrium.iv:Atrium:Sun"),
                       ::testing::ValuesIn(kScreenMethods)),
    [](const ::testing::TestParamInfo<std::tuple<const char*, const char*>>& info) {
      const std::string n = std::get<0>(info.param);
      return n.substr(0, n.find('.')) + methodParamName(std::get<1>(info.param));
    });

}  // namespace
}  // namespace ivshadow::test
