// Frame time of plain Coin rendering through the headless renderer: the baseline the shadow
// and peeling passes are measured against. Run: build/bin/ivshadow_bench
// (--benchmark_format=json for machines). Times are wall clock to glFinish per frame.
#include "callbacks/GlCapabilities.h"
#include "headless/OffscreenRenderer.h"
#include "ivshadow/IvShadowInit.h"
#include "scene/SceneLoader.h"
#include "scene/TransparencyType.h"
#include "scene/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoSeparator.h>

#include <benchmark/benchmark.h>

#include <string>

namespace {

void renderScene(benchmark::State& state, const std::string& sceneName,
                 SoGLRenderAction::TransparencyType transparency) {
  ivshadow::init();
  const int width = static_cast<int>(state.range(0));
  const int height = static_cast<int>(state.range(1));
  std::string error;
  auto renderer = ivshadow::OffscreenRenderer::create(width, height, error);
  if (!renderer) {
    state.SkipWithError(error.c_str());
    return;
  }
  renderer->action().setTransparencyType(transparency);
  ivshadow::LoadedScene scene =
      ivshadow::loadScene(std::string(IVSHADOW_SCENES_DIR) + "/" + sceneName);
  const ivshadow::ViewSetup view = ivshadow::ViewSetup::prepare(
      scene.root.get(), SbViewportRegion(static_cast<short>(width), static_cast<short>(height)));
  renderer->render(view.root.get());  // first frame builds Coin's caches
  for (auto _ : state) {
    const auto timing = renderer->render(view.root.get());
    state.SetIterationTime(timing.wallMs * 1e-3);
  }
  state.SetLabel(ivshadow::transparencyTypeName(transparency) + " on " +
                 renderer->capabilities().renderer);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Args({640, 480})->Args({1920, 1080})->UseManualTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(renderScene, glasses_blend, "coloured_glasses.iv", SoGLRenderAction::BLEND)
    ->Apply(sizes);
BENCHMARK_CAPTURE(renderScene, glasses_sorted_layers, "coloured_glasses.iv",
                  SoGLRenderAction::SORTED_LAYERS_BLEND)
    ->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
