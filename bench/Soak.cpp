// Soak run: renders a scene for many frames with its deep shadow light moving every frame
// (so the map is rebuilt, or the rays traced again, each time), or creates and destroys GL
// contexts, and samples the resident set size. Prints one JSON object: the samples and the
// least-squares slope of RSS over the second half of the run, in KiB per 1,000 frames (or
// cycles), the figure docs/RELIABILITY.md states. Driven by bench/soak.sh.
//   ivshadow_soak SCENE.iv --frames N [--set NAME.field=VALUE ...] [--move LIGHT] [--size WxH]
//   ivshadow_soak --contexts N
#include "headless/OffscreenRenderer.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene_input/FieldAssignment.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

long residentKiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

// Slope of y over x by least squares, over the second half of the samples: the first half
// holds the warm-up (Mesa's shader cache, Coin's caches, Embree's pools).
double slopePerThousand(const std::vector<std::pair<long, long>>& samples) {
  const std::size_t first = samples.size() / 2;
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = first; i < samples.size(); ++i) {
    const double x = double(samples[i].first), y = double(samples[i].second);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double d = n * sxx - sx * sx;
  return d > 0 ? 1000.0 * (n * sxy - sx * sy) / d : 0.0;
}

void print(const std::vector<std::pair<long, long>>& samples, const char* unit) {
  std::cout << "{\"unit\": \"" << unit << "\", \"samples\": [";
  for (std::size_t i = 0; i < samples.size(); ++i)
    std::cout << (i ? ", " : "") << "[" << samples[i].first << ", " << samples[i].second << "]";
  std::cout << "], \"rss_kib_first\": " << samples.front().second
            << ", \"rss_kib_last\": " << samples.back().second
            << ", \"slope_kib_per_1000\": " << slopePerThousand(samples) << "}\n";
}

int usage() {
  std::cerr << "usage: ivshadow_soak SCENE.iv --frames N [--set NAME.field=VALUE ...] "
               "[--move LIGHT] [--size WxH] | ivshadow_soak --contexts N\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ivshadow;
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string scenePath, move;
  std::vector<std::string> assignments;
  long frames = 0, contexts = 0;
  int width = 160, height = 120;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool more = i + 1 < args.size();
    if (args[i] == "--frames" && more)
      frames = std::stol(args[++i]);
    else if (args[i] == "--contexts" && more)
      contexts = std::stol(args[++i]);
    else if (args[i] == "--set" && more)
      assignments.push_back(args[++i]);
    else if (args[i] == "--move" && more)
      move = args[++i];
    else if (args[i] == "--size" && more)
      std::sscanf(args[++i].c_str(), "%dx%d", &width, &height);
    else if (scenePath.empty() && args[i][0] != '-')
      scenePath = args[i];
    else
      return usage();
  }
  init();
  std::vector<std::pair<long, long>> samples;
  if (contexts > 0) {
    for (long cycle = 0; cycle < contexts; ++cycle) {
      std::string error;
      auto renderer = OffscreenRenderer::create(width, height, error);
      if (!renderer) {
        std::cerr << error << '\n';
        return 3;
      }
      SoSeparator* empty = new SoSeparator;
      empty->ref();
      renderer->render(empty);
      empty->unref();
      if (cycle % 10 == 0) samples.emplace_back(cycle, residentKiB());
    }
    print(samples, "contexts");
    return 0;
  }
  if (scenePath.empty() || frames <= 0) return usage();
  LoadedScene scene = loadScene(scenePath);
  for (const std::string& text : assignments)
    FieldAssignment::parse(text).apply(scene.root.get(), scenePath);
  const ViewSetup view =
      ViewSetup::prepare(scene.root.get(), SbViewportRegion(short(width), short(height)));
  auto* light =
      move.empty() ? nullptr : dynamic_cast<SoDeepShadowLight*>(SoNode::getByName(move.c_str()));
  if (!move.empty() && light == nullptr) {
    std::cerr << "no DeepShadowLight named " << move << '\n';
    return 2;
  }
  const SbVec3f home = light ? light->location.getValue() : SbVec3f(0.0f, 0.0f, 0.0f);
  std::string error;
  auto renderer = OffscreenRenderer::create(width, height, error);
  if (!renderer) {
    std::cerr << error << '\n';
    return 3;
  }
  const long every = std::max(1L, frames / 100);
  for (long frame = 0; frame < frames; ++frame) {
    // A small circle around where the light was: every frame needs a new map or trace.
    if (light) {
      const float angle = float(frame) * 0.05f;
      light->location.setValue(home + SbVec3f(0.1f * std::cos(angle), 0.1f * std::sin(angle), 0));
    }
    renderer->render(view.root.get());
    if (frame % every == 0) samples.emplace_back(frame, residentKiB());
  }
  print(samples, "frames");
  return 0;
}
