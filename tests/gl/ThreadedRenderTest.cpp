// Two renderers on two threads at once, each with its own headless EGL context and its own
// graph: the plugin's process-wide state (warning sets, the Embree device, the pass-timing
// switch) is shared between them, its per-context state is not. Coin (Debian's 4.0 build, with
// threads but not COIN_THREADSAFE: Coin_HAVE_SAFETHREAD 0) locks its GL glue and cache-context
// tables, but not its name dictionaries or notification counter; so the graphs are read and
// their fields set on the main thread before the threads start, and the threads only render.
#include "image_files/ImageComparison.h"
#include "image_files/PngFile.h"
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"
#include "tests/support/TestSupport.h"

#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace ivshadow {
namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr int kFrames = 3;  // per graph: the first builds or traces, the others reuse

// The bundled demo (coloured panes, a glass sphere, a textured tile, peeled transparency)
// on GL's path, with its deep shadow light's method and a map small enough for llvmpipe.
std::string demoScene(const std::string& method) {
  std::ifstream in(test::scenesDir() + "/coloured_shadows.iv");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  // GL's path (the default, AUTO, traces on a software rasteriser); a map's size for a map.
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"DEF Scene TransparentShadowGroup {",
                                            "DEF Scene TransparentShadowGroup { renderer RASTER"},
        {"intensity 0.95",
         "intensity 0.95 method " + method +
             (method == "MAP" ? std::string(" resolution 256") : std::string())}}) {
    const std::size_t at = scene.find(from);
    if (at == std::string::npos) throw std::runtime_error("coloured_shadows.iv changed");
    scene.replace(at, from.size(), to);
  }
  return scene;
}

struct Graphs {
  SoSeparator* map = nullptr;
  SoSeparator* rays = nullptr;
  Graphs() : map(test::readIv(demoScene("MAP"))), rays(test::readIv(demoScene("RAYS"))) {}
  ~Graphs() {
    map->unref();
    rays->unref();
  }
};

struct Pictures {
  Image map;
  Image rays;
  std::string error;
};

// Renders each graph kFrames times in a new context made on the calling thread.
void renderBoth(const Graphs& graphs, Pictures& out) {
  std::string error;
  auto renderer = test::CheckedRenderer::create(kWidth, kHeight, error);
  if (!renderer) {
    out.error = "no headless GL context: " + error;
    return;
  }
  for (int frame = 0; frame < kFrames; ++frame) renderer->render(graphs.map);
  out.map = renderer->read();
  for (int frame = 0; frame < kFrames; ++frame) renderer->render(graphs.rays);
  out.rays = renderer->read();
}

int maxError(const Image& a, const Image& b) {
  return ImageComparison::compare(a, b, "threaded", "alone").all.maxError;
}

// The same code on the same rasteriser, each context with its own maps, traces and targets:
// the pictures must be identical (no tolerance). Two black pictures would be identical too:
// the one drawn alone must show the lit scene.
// It failed at random while Coin's render caches were replayed inside the group's passes (one
// context drew the group unshaded: docs/RELIABILITY.md, "Threads").
TEST(ThreadedRender, TwoContextsOnTwoThreadsDrawWhatOneContextDrawsAlone) {
  init();
  Pictures alone;
  {
    const Graphs graphs;
    renderBoth(graphs, alone);
  }
  ASSERT_TRUE(alone.error.empty()) << alone.error;
  const Image black(kWidth, kHeight);
  ASSERT_GT(maxError(alone.map, black), 100) << "the single-threaded picture is black";

  const Graphs first, second;
  Pictures a, b;
  std::thread one([&] { renderBoth(first, a); });
  std::thread two([&] { renderBoth(second, b); });
  one.join();
  two.join();
  const std::string dir = test::outputDir();
  writePng(dir + "/alone_map.png", alone.map);
  writePng(dir + "/alone_rays.png", alone.rays);
  int thread = 0;
  for (const Pictures* threaded : {&a, &b}) {
    ASSERT_TRUE(threaded->error.empty()) << threaded->error;
    // Kept for a failure to be looked at.
    const std::string name = dir + "/thread" + std::to_string(thread++);
    writePng(name + "_map.png", threaded->map);
    writePng(name + "_rays.png", threaded->rays);
    EXPECT_EQ(maxError(threaded->map, alone.map), 0) << name << "_map.png";
    EXPECT_EQ(maxError(threaded->rays, alone.rays), 0) << name << "_rays.png";
  }
}

}  // namespace
}  // namespace ivshadow
