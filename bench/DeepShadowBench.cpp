// Deep shadow map cost on the headless renderer: map build time against resolution, layers
// and triangle count, frame time with a built map, and frame time against Coin's own
// SoShadowGroup on the same opaque scene. Run: build/bin/ivshadow_bench
// --benchmark_filter='Map|Frame|Coin'. Times are wall clock, GPU finished.
#include "BenchScenes.h"
#include "headless/OffscreenRenderer.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"

#include <Inventor/nodes/SoSeparator.h>

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

namespace {

using ivshadow::bench::Shadows;

constexpr int kWidth = 640;
constexpr int kHeight = 480;

struct Fixture {
  std::unique_ptr<ivshadow::OffscreenRenderer> renderer;
  SoSeparator* root = nullptr;
  SoDeepShadowLight* light = nullptr;

  Fixture(benchmark::State& state, int triangles, bool transparent, Shadows shadows) {
    ivshadow::init();
    std::string error;
    renderer = ivshadow::OffscreenRenderer::create(kWidth, kHeight, error);
    if (!renderer) {
      state.SkipWithError(error.c_str());
      return;
    }
    root = ivshadow::bench::sphereField(triangles, transparent, shadows, kWidth, kHeight);
    light = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
    // These benchmarks measure the map, whatever AUTO would pick on this renderer.
    if (light != nullptr) light->method = SoDeepShadowLight::MAP;
  }
  ~Fixture() {
    renderer.reset();
    if (root) root->unref();
  }
  ivshadow::DeepShadowStatistics stats() const {
    return ivshadow::collectDeepShadowStatistics(root);
  }
};

void reportMap(benchmark::State& state, const ivshadow::DeepShadowStatistics& stats) {
  if (stats.lights.empty()) return;
  const auto& light = stats.lights[0];
  int layers = 0;
  for (int used : light.layersUsed) layers += used;
  state.counters["map_MB"] = double(light.bytes) / 1048576.0;
  state.counters["peak_MB"] = double(light.peakBytes) / 1048576.0;
  state.counters["layers"] = layers;
  state.counters["triangles"] = stats.casterTriangles;
}

// Args: triangles, resolution, maxLayers. Each iteration moves nothing but touches the light,
// which rebuilds its map; the time is the build alone.
void MapBuild(benchmark::State& state) {
  Fixture f(state, int(state.range(0)), true, Shadows::DeepShadowGroup);
  if (!f.renderer) return;
  f.light->resolution = int(state.range(1));
  f.light->maxLayers = int(state.range(2));
  f.renderer->render(f.root);  // compiles the programs and builds the first map
  for (auto _ : state) {
    f.light->location.touch();
    f.renderer->render(f.root);
    state.SetIterationTime(f.stats().lastBuildMs * 1e-3);
  }
  reportMap(state, f.stats());
}

// Args: triangles, resolution, maxLayers. Frame time with the map already built.
void FrameWithMap(benchmark::State& state) {
  Fixture f(state, int(state.range(0)), true, Shadows::DeepShadowGroup);
  if (!f.renderer) return;
  f.light->resolution = int(state.range(1));
  f.light->maxLayers = int(state.range(2));
  f.renderer->render(f.root);
  for (auto _ : state) state.SetIterationTime(f.renderer->render(f.root).wallMs * 1e-3);
  reportMap(state, f.stats());
}

// Args: precision (SoDeepShadowLight::Precision), shadowColor (ShadowColor). Build time and
// memory of the 10k-triangle glass scene at 512 / 4 layers for each storage format.
void MapFormats(benchmark::State& state) {
  Fixture f(state, 10000, true, Shadows::DeepShadowGroup);
  if (!f.renderer) return;
  f.light->precision = int(state.range(0));
  f.light->shadowColor = int(state.range(1));
  f.renderer->render(f.root);
  for (auto _ : state) {
    f.light->location.touch();
    f.renderer->render(f.root);
    state.SetIterationTime(f.stats().lastBuildMs * 1e-3);
  }
  reportMap(state, f.stats());
  state.SetLabel(std::string(state.range(0) == SoDeepShadowLight::HALF ? "HALF" : "FLOAT") +
                 (state.range(1) == SoDeepShadowLight::COLORED ? " COLORED" : " MONOCHROME"));
}

// Arg: Shadows. The same opaque scene (10k triangles) with no shadows, Coin's SoShadowGroup
// (spot light) and the deep shadow group (point light, default map), maps already built.
void CoinComparison(benchmark::State& state) {
  const auto shadows = Shadows(state.range(0));
  Fixture f(state, 10000, false, shadows);
  if (!f.renderer) return;
  for (int i = 0; i < 2; ++i) f.renderer->render(f.root);
  for (auto _ : state) state.SetIterationTime(f.renderer->render(f.root).wallMs * 1e-3);
  state.SetLabel(shadows == Shadows::None              ? "plain Coin"
                 : shadows == Shadows::CoinShadowGroup ? "SoShadowGroup"
                                                       : "SoTransparentShadowGroup");
}

void common(benchmark::internal::Benchmark* b) {
  b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);
}

// Resolution, layers and triangles each varied around 512 / 4 / 10k.
BENCHMARK(MapBuild)
    ->Args({10000, 256, 4})
    ->Args({10000, 512, 4})
    ->Args({10000, 1024, 4})
    ->Args({10000, 512, 1})
    ->Args({10000, 512, 2})
    ->Args({10000, 512, 8})
    ->Args({1000, 512, 4})
    ->Args({100000, 512, 4})
    ->Args({1000000, 512, 4})
    ->Apply(common);
BENCHMARK(FrameWithMap)
    ->Args({10000, 512, 4})
    ->Args({10000, 1024, 4})
    ->Args({100000, 512, 4})
    ->Args({1000000, 512, 4})
    ->Apply(common);
BENCHMARK(MapFormats)
    ->Args({SoDeepShadowLight::FLOAT, SoDeepShadowLight::COLORED})
    ->Args({SoDeepShadowLight::HALF, SoDeepShadowLight::COLORED})
    ->Args({SoDeepShadowLight::FLOAT, SoDeepShadowLight::MONOCHROME})
    ->Args({SoDeepShadowLight::HALF, SoDeepShadowLight::MONOCHROME})
    ->Apply(common);
BENCHMARK(CoinComparison)
    ->Arg(int(Shadows::None))
    ->Arg(int(Shadows::CoinShadowGroup))
    ->Arg(int(Shadows::DeepShadowGroup))
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10);

}  // namespace
