#include "image_files/PngFile.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace ivshadow {
namespace {

using test::readText;
using test::runOnTestDisplay;

nlohmann::json readJson(const std::string& path) {
  return nlohmann::json::parse(readText(path));
}

std::vector<std::string> setArguments(const std::vector<std::string>& assignments) {
  std::vector<std::string> out;
  for (const std::string& a : assignments) {
    out.push_back("--set");
    out.push_back(a);
  }
  return out;
}

// What a scripted viewer run with field changes made through its panel produced, and
// `ivshadow render` of the same scene with the same changes made by Coin's SoField::set (an
// independent path: the CLI's --set, not the panel's editors).
struct PanelRun {
  Image viewer, headless, headlessUnchanged;
  nlohmann::json figures, stats;
};

// Tolerances: viewer and headless render draw with the same Coin and nodes on llvmpipe,
// through GLX and EGL. Measured for every case below: at most 0.005 % of the pixels differ by
// more than 2 steps (edges where transparent surfaces meet); 99.9 % leaves room for a few
// more without letting a setting that did not apply pass, since each setting below changes
// 12 % or more of the picture: against the unchanged render, more than 10 % must change.
constexpr double kSameShare = 0.999;
constexpr double kChangedShare = 0.90;

PanelRun runPanel(const std::string& sceneName, const std::vector<std::string>& assignments) {
  const std::string transparency = test::kViewerTransparency;
  const std::string dir = test::outputDir();
  const std::string scene = test::scenesDir() + "/" + sceneName;
  std::vector<std::string> viewer = {
      test::viewerExe(),     "--screenshot", dir + "/viewer.png", "--figures",
      dir + "/figures.json", "--size",       "320x240",           scene};
  const std::vector<std::string> sets = setArguments(assignments);
  viewer.insert(viewer.end(), sets.begin(), sets.end());

  std::vector<std::string> render = {
      test::ivshadowExe(),   "render",         scene,       "-o",
      dir + "/headless.png", "--size",         "320x240",   "--stats",
      dir + "/stats.json",   "--transparency", transparency};
  render.insert(render.end(), sets.begin(), sets.end());
  const test::ProcessResult rendered = test::run(render);
  EXPECT_EQ(rendered.exitCode, 0) << rendered.err;
  const test::ProcessResult unchanged =
      test::run({test::ivshadowExe(), "render", scene, "-o", dir + "/headless_unchanged.png",
                 "--size", "320x240", "--transparency", transparency});
  EXPECT_EQ(unchanged.exitCode, 0) << unchanged.err;

  PanelRun run;
  run.headless = readPng(dir + "/headless.png");
  test::ProcessResult shown;
  run.viewer = test::viewerScreenshot(viewer, dir + "/viewer.png", shown);
  EXPECT_EQ(shown.exitCode, 0) << shown.out << shown.err;
  run.headlessUnchanged = readPng(dir + "/headless_unchanged.png");
  run.figures = readJson(dir + "/figures.json");
  run.stats = readJson(dir + "/stats.json");
  return run;
}

// The panel's live figures of the screenshot frame report the same maps as the headless
// render's statistics: the same layers per cube face and the same bytes (both count what
// the same nodes built for the same settings, so they must agree exactly).
void expectSameMaps(const PanelRun& run) {
  ASSERT_EQ(run.figures["dsm_layers_used"].size(), run.stats["dsm_layers_used"].size());
  for (std::size_t i = 0; i < run.figures["dsm_layers_used"].size(); ++i) {
    EXPECT_EQ(run.figures["dsm_layers_used"][i]["faces"], run.stats["dsm_layers_used"][i]["faces"]);
    EXPECT_EQ(run.figures["dsm_layers_used"][i]["bytes"], run.stats["dsm_layers_used"][i]["bytes"]);
    EXPECT_EQ(run.figures["dsm_layers_used"][i]["resolution"],
              run.stats["dsm_layers_used"][i]["resolution"]);
  }
  EXPECT_EQ(run.figures["dsm_bytes"], run.stats["dsm_bytes"]);
  EXPECT_EQ(run.figures["peel_passes"], run.stats["peel_passes"]);
}

TEST(ViewerPanel, LightFieldsSetThroughThePanelRenderAsHeadlessWithTheSameFields) {
  const PanelRun run = runPanel(
      "coloured_shadows.iv",
      {"Scene.renderer=RASTER", "Lamp.method=MAP", "Lamp.resolution=256", "Lamp.maxLayers=2",
       "Lamp.colorModel=POWER", "Lamp.shadowColor=MONOCHROME", "Lamp.precision=HALF",
       "Lamp.filter=PCF", "Lamp.filterSize=5", "Lamp.bias=3", "Lamp.layerOverflow=TRUNCATE"});
  test::expectMostlyEqual(run.viewer, run.headless, 2, kSameShare, "viewer against headless");
  EXPECT_LT(test::shareWithin(run.viewer, run.headlessUnchanged, 2), kChangedShare)
      << "the settings made no visible difference";
  expectSameMaps(run);
  ASSERT_EQ(run.figures["dsm_layers_used"].size(), 1u);
  EXPECT_EQ(run.figures["dsm_layers_used"][0]["resolution"], 256);
  EXPECT_EQ(run.figures["dsm_layers_used"][0]["colored"], false);
  // maxLayers 2, and the closing layer of a face whose layers ran out (DeepShadowMap.h).
  for (int layers : run.figures["dsm_layers_used"][0]["faces"]) EXPECT_LE(layers, 2 + 1);
}

TEST(ViewerPanel, SwitchingTheGroupOffThroughThePanelRendersAsHeadless) {
  const PanelRun run = runPanel("coloured_shadows.iv", {"Scene.isActive=FALSE"});
  test::expectMostlyEqual(run.viewer, run.headless, 2, kSameShare, "viewer against headless");
  EXPECT_LT(test::shareWithin(run.viewer, run.headlessUnchanged, 2), kChangedShare);
  // An inactive group builds no map.
  EXPECT_EQ(run.figures["dsm_bytes"], 0);
}

TEST(ViewerPanel, TheBounceSwitchedOffThroughThePanelRendersAsHeadless) {
  // bounce_wall.iv's wall shows only the bounce: off, it goes black in both.
  const PanelRun run = runPanel("bounce_wall.iv", {"Room.bounce=FALSE"});
  test::expectMostlyEqual(run.viewer, run.headless, 2, kSameShare, "viewer against headless");
  EXPECT_LT(test::shareWithin(run.viewer, run.headlessUnchanged, 2), kChangedShare)
      << "switching the bounce off made no visible difference";
  EXPECT_EQ(run.stats["bounce_lights"], 0);
}

TEST(ViewerPanel, PeelingAndLightLocationSetThroughThePanelRenderAsHeadless) {
  const PanelRun run =
      runPanel("peeled_glasses.iv",
               {"Shelf.renderer=RASTER", "Lamp.method=MAP", "Glasses.method=FRONT_TO_BACK",
                "Glasses.maxPasses=2", "Lamp.location=-1 1 3"});
  test::expectMostlyEqual(run.viewer, run.headless, 2, kSameShare, "viewer against headless");
  EXPECT_LT(test::shareWithin(run.viewer, run.headlessUnchanged, 2), kChangedShare);
  expectSameMaps(run);
  // maxPasses caps the passes, the depth-range pass included.
  EXPECT_EQ(run.figures["peel_passes"], 2);
}

TEST(ViewerPanel, SavedSceneHoldsThePanelsValues) {
  const std::string dir = test::outputDir();
  const std::string scene = test::scenesDir() + "/coloured_shadows.iv";
  const std::vector<std::string> sets = {"Lamp.resolution=256", "Lamp.shadowColor=MONOCHROME",
                                         "Lamp.location=1 -1 3.5"};
  std::vector<std::string> viewer = {test::viewerExe(), scene, "--save-scene", dir + "/saved.iv"};
  for (const std::string& a : setArguments(sets)) viewer.push_back(a);
  const test::ProcessResult saved = runOnTestDisplay(viewer);
  ASSERT_EQ(saved.exitCode, 0) << saved.err;
  EXPECT_NE(saved.out.find("wrote " + dir + "/saved.iv"), std::string::npos) << saved.out;
  const std::string text = readText(dir + "/saved.iv");
  EXPECT_NE(text.find("resolution 256"), std::string::npos) << text;
  EXPECT_NE(text.find("shadowColor MONOCHROME"), std::string::npos) << text;
  EXPECT_EQ(text.find("Dragger"), std::string::npos) << "the viewer's dragger was saved";

  // The saved file renders exactly as the original with the same fields set by the CLI.
  std::vector<std::string> original = {test::ivshadowExe(),       "render", scene,    "-o",
                                       dir + "/original_set.png", "--size", "160x120"};
  for (const std::string& a : setArguments(sets)) original.push_back(a);
  ASSERT_EQ(test::run(original).exitCode, 0);
  ASSERT_EQ(test::run({test::ivshadowExe(), "render", dir + "/saved.iv", "-o", dir + "/saved.png",
                       "--size", "160x120"})
                .exitCode,
            0);
  // Same renderer, same scene, but Coin writes floats with 8 significant digits, which does
  // not always give back the same float (measured: 2 of 19,200 pixels 1 step off); 1 step on
  // 99.9 % of the pixels still fails any field that was not saved.
  test::expectMostlyEqual(readPng(dir + "/saved.png"), readPng(dir + "/original_set.png"), 1, 0.999,
                          "render of the saved scene against the original with --set");
}

TEST(ViewerPanel, AddLightWrapsASceneWithoutDeepShadowsInAGroupWithALight) {
  const std::string dir = test::outputDir();
  const test::ProcessResult result = runOnTestDisplay(
      {test::viewerExe(), test::scenesDir() + "/no_camera.iv", "--add-light", "--set",
       "ShadowLight.resolution=128", "--set", "ShadowLight.method=MAP", "--set",
       "ShadowGroup.renderer=RASTER", "--save-scene", dir + "/wrapped.iv", "--screenshot",
       dir + "/viewer.png", "--figures", dir + "/figures.json", "--size", "320x240"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string text = readText(dir + "/wrapped.iv");
  EXPECT_NE(text.find("DEF ShadowGroup TransparentShadowGroup"), std::string::npos) << text;
  EXPECT_NE(text.find("DEF ShadowLight DeepShadowLight"), std::string::npos) << text;
  EXPECT_NE(text.find("Cube"), std::string::npos) << text;

  // The viewer shows what a headless render of the saved file shows: the new light, not the
  // headlight (same tolerance as the panel tests).
  ASSERT_EQ(
      test::run({test::ivshadowExe(), "render", dir + "/wrapped.iv", "-o", dir + "/headless.png",
                 "--size", "320x240", "--transparency", test::kViewerTransparency})
          .exitCode,
      0);
  const Image viewer = readPng(dir + "/viewer.png");
  test::expectMostlyEqual(viewer, readPng(dir + "/headless.png"), 2, kSameShare,
                          "viewer against headless render of the saved scene");
  EXPECT_GT(test::shareLit(viewer), 0.05) << "the new light lights (nearly) nothing";
  // The light's map was built and holds the two shapes on some face.
  const nlohmann::json figures = readJson(dir + "/figures.json");
  ASSERT_EQ(figures["dsm_layers_used"].size(), 1u);
  EXPECT_EQ(figures["dsm_layers_used"][0]["light"], "ShadowLight");
  EXPECT_EQ(figures["dsm_layers_used"][0]["resolution"], 128);
  int layers = 0;
  for (int n : figures["dsm_layers_used"][0]["faces"]) layers += n;
  EXPECT_GT(layers, 0);
  EXPECT_EQ(figures["dsm_rebuilds"], 1);
}

// The panel's figures of one screenshot frame (the frame after the first, which built what the
// scene needs: the screenshot frame is a still one).
nlohmann::json frameFigures(const std::vector<std::string>& assignments) {
  const std::string dir = test::outputDir();
  std::vector<std::string> command = {test::viewerExe(), test::scenesDir() + "/coloured_shadows.iv",
                                      "--screenshot",    dir + "/viewer.png",
                                      "--figures",       dir + "/figures.json",
                                      "--size",          "320x240"};
  for (const std::string& a : setArguments(assignments)) command.push_back(a);
  const test::ProcessResult result = runOnTestDisplay(command);
  EXPECT_EQ(result.exitCode, 0) << result.err;
  return result.exitCode == 0 ? readJson(dir + "/figures.json") : nlohmann::json();
}

// Every "N ms" of the panel's lines lies within the frame's wall time: no figure of an earlier
// frame (a trace of 403 ms beside a frame of 92 ms) or an impossible timer is shown.
void expectNoTimeAboveTheFrame(const nlohmann::json& figures) {
  const std::string text = figures["panel_text"];
  const double frame = figures["frame_ms"];
  const std::regex time("([0-9.]+) ms");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), time); it != std::sregex_iterator();
       ++it) {
    EXPECT_LE(std::stod((*it)[1]), frame + 1.0) << text;
  }
  EXPECT_NE(text.find(" fps"), std::string::npos) << text;
}

TEST(ViewerPanel, FiguresNameWhatTheTracedPathDidThisFrame) {
  const nlohmann::json figures = frameFigures({"Scene.renderer=TRACER"});
  ASSERT_TRUE(figures.is_object());
  const std::string text = figures["panel_text"];
  EXPECT_EQ(figures["group_paths"]["Scene"], "TRACER");
  EXPECT_NE(text.find("path  TRACER"), std::string::npos) << text;
  // The traced group keeps its picture on a still frame and has no maps or shadow rays of its
  // own: no line of the GL path's passes, and its light is not called a ray-traced light.
  EXPECT_NE(text.find("trace kept"), std::string::npos) << text;
  EXPECT_NE(text.find("Scene: traced, no maps"), std::string::npos) << text;
  for (const char* stale : {"map ", "peel ", "rays ", "shade ", "Lamp:"})
    EXPECT_EQ(text.find(stale), std::string::npos) << stale << " in\n" << text;
  expectNoTimeAboveTheFrame(figures);
}

TEST(ViewerPanel, FiguresNameWhatTheGlPathDidThisFrame) {
  const nlohmann::json figures = frameFigures({"Scene.renderer=RASTER", "Lamp.method=MAP"});
  ASSERT_TRUE(figures.is_object());
  const std::string text = figures["panel_text"];
  EXPECT_EQ(figures["group_paths"]["Scene"], "RASTER");
  EXPECT_NE(text.find("path  RASTER"), std::string::npos) << text;
  // The still frame drew with the map the first frame built: the map is listed, its build
  // time is not (it was not built this frame), and nothing was traced.
  EXPECT_EQ(figures["this_frame"]["map_build"], false);
  EXPECT_NE(text.find("Lamp: MAP 512"), std::string::npos) << text;
  for (const char* stale : {"map ", "trace ", "rays "})
    EXPECT_EQ(text.find(stale), std::string::npos) << stale << " in\n" << text;
  EXPECT_NE(text.find("shade "), std::string::npos) << text;
  expectNoTimeAboveTheFrame(figures);
}

TEST(ViewerPanel, BadAssignmentsExitTwoNamingTheFieldAndWriteNothing) {
  const std::string dir = test::outputDir();
  struct Case {
    std::string assignment, message;
  };
  const std::vector<Case> cases = {
      {"Nope.resolution=64", "no deep shadow node named 'Nope' in"},
      {"Lamp.nosuch=1", "the shadow panel has no field 'nosuch' for 'Lamp'"},
      {"Lamp.resolution=abc", "cannot set Lamp.resolution to 'abc': expected an integer from 1"},
      {"Lamp.maxLayers=65", "cannot set Lamp.maxLayers to '65': expected an integer from 1 to 64"},
      {"Lamp.shadowColor=PURPLE", "expected one of AUTO, MONOCHROME, COLORED"},
      {"Lamp.location=1 2", "expected three numbers"},
      {"Lamp.resolution", "expected NAME.field=VALUE"},
  };
  for (const Case& c : cases) {
    const test::ProcessResult result = runOnTestDisplay(
        {test::viewerExe(), test::scenesDir() + "/coloured_shadows.iv", "--set", c.assignment,
         "--screenshot", dir + "/shot.png", "--save-scene", dir + "/saved.iv"});
    EXPECT_EQ(result.exitCode, 2) << c.assignment << ": " << result.err;
    EXPECT_NE(result.err.find(c.message), std::string::npos) << c.assignment << ": " << result.err;
    EXPECT_NE(result.err.find("--set '" + c.assignment + "'"), std::string::npos) << result.err;
    EXPECT_FALSE(test::fileExists(dir + "/shot.png")) << c.assignment;
    EXPECT_FALSE(test::fileExists(dir + "/saved.iv")) << c.assignment;
  }
}

TEST(ViewerPanel, UnwritableSceneOutputExitsTwoBeforeAnyOutput) {
  const std::string dir = test::outputDir();
  const test::ProcessResult result =
      runOnTestDisplay({test::viewerExe(), test::scenesDir() + "/no_camera.iv", "--screenshot",
                        dir + "/shot.png", "--save-scene", dir + "/missing/dir/saved.iv"});
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find("missing/dir/saved.iv"), std::string::npos) << result.err;
  EXPECT_FALSE(test::fileExists(dir + "/shot.png"));
}

TEST(ViewerPanel, RecentFilesListTheScenesOpenedNewestFirst) {
  const std::string dir = test::outputDir();
  const std::string first = test::scenesDir() + "/no_camera.iv";
  const std::string second = test::scenesDir() + "/lit_plane.iv";
  for (const std::string& scene : {first, second, first}) {
    const test::ProcessResult result =
        runOnTestDisplay({test::viewerExe(), scene, "--save-scene",
                          dir + "/" + std::filesystem::path(scene).filename().string()});
    ASSERT_EQ(result.exitCode, 0) << result.err;
  }
  // QSettings' file (XDG_CONFIG_HOME/ivshadow/viewer.conf): opened and saved files, newest
  // first, each once.
  const std::string conf = readText(dir + "/config/ivshadow/viewer.conf");
  const std::string savedFirst = dir + "/no_camera.iv", savedSecond = dir + "/lit_plane.iv";
  const std::string expected = "recentFiles=" + savedFirst + ", " +
                               std::filesystem::canonical(first).string() + ", " + savedSecond +
                               ", " + std::filesystem::canonical(second).string();
  EXPECT_NE(conf.find(expected), std::string::npos) << conf << "\nexpected: " << expected;
}

}  // namespace
}  // namespace ivshadow
