// The shadow methods (SoDeepShadowLight::method: MAP, RAYS, VOLUMES, OPACITY_MAP) on the
// headless renderer: frame time with a static scene and with the light moving every frame, at
// 1k / 100k / 1M triangles and 640 x 480 / 1920 x 1080, the opacity map against its slices,
// and the casters' Embree build against triangles. Run:
// build/bin/ivshadow_bench --benchmark_filter='MethodFrame|OpacitySlices|BvhBuild'; one
// bounce against none with --benchmark_filter=Bounce. RaysAgainstCoin puts
// RAYS and the group's renderer TRACER next to plain Coin (no shadows) in the same run:
// static, light moving, camera moving (--benchmark_filter=RaysAgainstCoin; arguments
// triangles, kind: 0 plain Coin, 1 RAYS PEELED, 2 RAYS COIN_BLENDING, 3 TRACER, 4 TRACER with
// movingResolution 0.5, motion), with
// the pass times of the last frame. Times are wall
// clock, GPU finished.
#include "BenchScenes.h"
#include "headless/OffscreenRenderer.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/PeelStatistics.h"
#include "ivshadow/ShadowMethod.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"

#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoSeparator.h>

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

namespace {

using ivshadow::bench::Shadows;

struct Scene {
  std::unique_ptr<ivshadow::OffscreenRenderer> renderer;
  SoSeparator* root = nullptr;
  SoDeepShadowLight* light = nullptr;

  // `shadows` None: plain Coin, `light` stays null and `method` is ignored.
  Scene(benchmark::State& state, int triangles, int width, int height, int method,
        Shadows shadows = Shadows::DeepShadowGroup) {
    ivshadow::init();
    std::string error;
    renderer = ivshadow::OffscreenRenderer::create(width, height, error);
    if (!renderer) {
      state.SkipWithError(error.c_str());
      return;
    }
    root = ivshadow::bench::sphereField(triangles, true, shadows, width, height);
    if (shadows == Shadows::DeepShadowGroup) {
      light = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
      light->method = method;
    }
    renderer->render(root);  // programs, caches, the first map or BVH and trace
  }
  ~Scene() {
    renderer.reset();
    if (root) root->unref();
  }
};

// Args: triangles, width, height, method (MAP 1 / RAYS 2 / VOLUMES 3 / OPACITY_MAP 4), moving
// (0 / 1). A moving light rebuilds the map (MAP, OPACITY_MAP with its default 4 slices),
// traces again (RAYS) or draws the volumes again (VOLUMES) in every frame; a static one
// reuses them.
void MethodFrame(benchmark::State& state) {
  Scene s(state, int(state.range(0)), int(state.range(1)), int(state.range(2)),
          int(state.range(3)));
  if (!s.renderer) return;
  const bool moving = state.range(4) != 0;
  const SbVec3f start = s.light->location.getValue();
  int frame = 0;
  for (auto _ : state) {
    if (moving) s.light->location.setValue(start + SbVec3f(0.05f * float(++frame % 7), 0.0f, 0.0f));
    state.SetIterationTime(s.renderer->render(s.root).wallMs * 1e-3);
  }
  const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(s.root);
  state.counters["triangles"] = stats.casterTriangles;
  state.counters["map_MB"] = stats.lights.empty() ? 0.0 : double(stats.lights[0].bytes) / 1048576.0;
  state.counters["bvh_MB"] = double(stats.bvhBytes) / 1048576.0;
  const int method = int(state.range(3));
  if (method == SoDeepShadowLight::MAP || method == SoDeepShadowLight::OPACITY_MAP)
    state.counters["build_ms"] = stats.lastBuildMs;
  if (method == SoDeepShadowLight::RAYS || method == SoDeepShadowLight::VOLUMES) {
    state.counters["capture_ms"] = stats.rayCaptureMs;  // the last trace's parts
    state.counters["trace_ms"] = stats.rayTraceMs;
    // VOLUMES: building the volumes on the CPU and drawing them, after the upload.
    state.counters["draw_ms"] = stats.raysMs - stats.rayCaptureMs - stats.rayTraceMs;
    state.counters["volume_faces"] = double(stats.volumeFaces);
    state.counters["layers"] = stats.rayLayers;
  }
  state.SetLabel(std::string(ivshadow::shadowMethodName(ivshadow::ShadowMethod(method))) +
                 (moving ? " moving light" : " static"));
}

// Args: triangles, slices. The opacity map rebuilt for a moving light at 640 x 480: the
// build's wall time (it waits for its draws) against the slices, one draw of the casters per
// face and kOpacitySlicesPerDraw slices, and the frame's.
void OpacitySlices(benchmark::State& state) {
  Scene s(state, int(state.range(0)), 640, 480, SoDeepShadowLight::OPACITY_MAP);
  if (!s.renderer) return;
  s.light->slices = int(state.range(1));
  s.renderer->render(s.root);
  const SbVec3f start = s.light->location.getValue();
  int frame = 0;
  double build = 0.0;
  for (auto _ : state) {
    s.light->location.setValue(start + SbVec3f(0.05f * float(++frame % 7), 0.0f, 0.0f));
    state.SetIterationTime(s.renderer->render(s.root).wallMs * 1e-3);
    build += ivshadow::collectDeepShadowStatistics(s.root).lastBuildMs;
  }
  const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(s.root);
  state.counters["build_ms"] = build / double(state.iterations());
  state.counters["draws_per_face"] = stats.lights.empty() ? 0 : stats.lights[0].passes[0];
  state.counters["map_MB"] = stats.lights.empty() ? 0.0 : double(stats.lights[0].bytes) / 1048576.0;
}

// Args: triangles, bounce lights (0: no bounce, the baseline in the same run), moving (0 /
// 1). One bounce (SoTransparentShadowGroup::bounce) over the sphere field at 640 x 480 with a
// RAYS light: a static frame pays the gather per pixel; a moving light also places the
// lights again on the CPU and draws their imperfect shadow maps.
void Bounce(benchmark::State& state) {
  Scene s(state, int(state.range(0)), 640, 480, SoDeepShadowLight::RAYS);
  if (!s.renderer) return;
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.apply(s.root);
  auto* group = static_cast<SoTransparentShadowGroup*>(search.getPath()->getTail());
  const int lights = int(state.range(1));
  group->bounce = lights > 0;
  if (lights > 0) group->bounceLights = lights;
  s.renderer->render(s.root);
  const bool moving = state.range(2) != 0;
  const SbVec3f start = s.light->location.getValue();
  int frame = 0;
  double place = 0.0, maps = 0.0;
  for (auto _ : state) {
    if (moving) s.light->location.setValue(start + SbVec3f(0.05f * float(++frame % 7), 0.0f, 0.0f));
    state.SetIterationTime(s.renderer->render(s.root).wallMs * 1e-3);
    const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(s.root);
    place += stats.bouncePlaceMs;
    maps += stats.bounceMapMs;
  }
  const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(s.root);
  state.counters["lights"] = stats.bounceLights;
  state.counters["triangles"] = stats.casterTriangles;
  if (moving) {
    state.counters["place_ms"] = place / double(state.iterations());
    state.counters["maps_ms"] = maps / double(state.iterations());
  }
  state.counters["bounce_MB"] = double(stats.bounceBytes) / 1048576.0;
  state.SetLabel(std::string(lights > 0 ? "bounce" : "no bounce") +
                 (moving ? " moving light" : " static"));
}

// Arg: triangles. Changing a caster's material rebuilds the casters and their Embree scene;
// the time is the BVH build alone.
void BvhBuild(benchmark::State& state) {
  Scene s(state, int(state.range(0)), 320, 240, SoDeepShadowLight::RAYS);
  if (!s.renderer) return;
  SoSearchAction search;
  search.setType(SoMaterial::getClassTypeId());
  search.apply(s.root);
  auto* material = static_cast<SoMaterial*>(search.getPath()->getTail());
  for (auto _ : state) {
    material->shininess.touch();
    s.renderer->render(s.root);
    state.SetIterationTime(ivshadow::collectDeepShadowStatistics(s.root).bvhBuildMs * 1e-3);
  }
  const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(s.root);
  state.counters["triangles"] = stats.casterTriangles;
  state.counters["bvh_MB"] = double(stats.bvhBytes) / 1048576.0;
  state.counters["bytes_per_triangle"] =
      stats.casterTriangles > 0 ? double(stats.bvhBytes) / stats.casterTriangles : 0.0;
}

// Args: triangles, shadows (0 plain Coin; 1 RAYS, the group's default transparency PEELED;
// 2 RAYS, transparency COIN_BLENDING, blended as plain Coin blends; 3 renderer TRACER; 4 the
// same with movingResolution 0.5: every frame after the first of a motion traced at 400 x
// 300), motion (0 static, 1 light moving, 2 camera moving), at 800 x 600. Plain Coin's light and
// camera move as RAYS's do, so each ratio compares the same frames.
void RaysAgainstCoin(benchmark::State& state) {
  const int shadows = int(state.range(1));
  Scene s(state, int(state.range(0)), 800, 600, SoDeepShadowLight::RAYS,
          shadows != 0 ? Shadows::DeepShadowGroup : Shadows::None);
  if (!s.renderer) return;
  const int motion = int(state.range(2));
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.apply(s.root);
  auto* group =
      shadows != 0 ? static_cast<SoTransparentShadowGroup*>(search.getPath()->getTail()) : nullptr;
  if (shadows == 2) {
    group->transparency = SoTransparentShadowGroup::COIN_BLENDING;
    s.renderer->render(s.root);  // the blending program variants
  }
  if (shadows >= 3) {
    group->renderer = SoTransparentShadowGroup::TRACER;
    if (shadows == 4) group->movingResolution = 0.5f;
    s.renderer->render(s.root);  // the subgraph read for the tracer, the first trace
    // The first still frame composites the picture and keeps what that leaves; the still
    // frames after it, the ones timed, put that back.
    if (motion == 0) s.renderer->render(s.root);
  }
  search.setType(SoCamera::getClassTypeId());
  search.apply(s.root);
  auto* camera = static_cast<SoCamera*>(search.getPath()->getTail());
  search.setType(SoPointLight::getClassTypeId());  // a SoDeepShadowLight is one too
  search.apply(s.root);
  auto* light = static_cast<SoPointLight*>(search.getPath()->getTail());
  const SbVec3f eye = camera->position.getValue();
  const SbVec3f lamp = light->location.getValue();
  int frame = 0;
  for (auto _ : state) {
    const float step = 0.05f * float(++frame % 7);
    if (motion == 1) light->location.setValue(lamp + SbVec3f(step, 0.0f, 0.0f));
    if (motion == 2) camera->position.setValue(eye + SbVec3f(step, 0.0f, 0.0f));
    state.SetIterationTime(s.renderer->render(s.root).wallMs * 1e-3);
  }
  if (shadows != 0) {
    // The last frame's parts: a static frame traces nothing and keeps the last trace's.
    const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(s.root);
    const ivshadow::PeelStatistics peel = ivshadow::collectPeelStatistics(s.root);
    state.counters["triangles"] = stats.casterTriangles;
    state.counters["capture_ms"] = stats.rayCaptureMs;
    state.counters["trace_ms"] = stats.rayTraceMs;
    state.counters["upload_ms"] = stats.raysMs - stats.rayCaptureMs - stats.rayTraceMs;
    state.counters["layers"] = stats.rayLayers;
    state.counters["peel_ms"] = peel.peelMs;
    state.counters["peel_passes"] = peel.passes;
    state.counters["tracer_ms"] = stats.tracerMs;
    state.counters["tracer_scene_ms"] = stats.tracerSceneMs;
    state.counters["tracer_lights_ms"] = stats.tracerLightsMs;
    state.counters["tracer_width"] = stats.tracerWidth;
  }
  static const char* const kinds[5] = {"plain Coin", "RAYS PEELED", "RAYS COIN_BLENDING",
                                       "renderer TRACER", "TRACER movingResolution 0.5"};
  static const char* const motions[3] = {" static", " light moving", " camera moving"};
  state.SetLabel(std::string(kinds[shadows]) + motions[motion]);
}

void frames(benchmark::internal::Benchmark* b) {
  for (int triangles : {1000, 100000, 1000000})
    for (const auto& size : {std::pair<int, int>{640, 480}, std::pair<int, int>{1920, 1080}})
      for (int method : {int(SoDeepShadowLight::MAP), int(SoDeepShadowLight::RAYS),
                         int(SoDeepShadowLight::VOLUMES), int(SoDeepShadowLight::OPACITY_MAP)})
        for (int moving : {0, 1}) b->Args({triangles, size.first, size.second, method, moving});
  b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);
}

BENCHMARK(MethodFrame)->Apply(frames);
BENCHMARK(Bounce)
    ->ArgsProduct({{1000, 100000}, {0, 64, 256}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(OpacitySlices)
    ->ArgsProduct({{1000, 100000}, {1, 4, 7, 8, 16, 32}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(RaysAgainstCoin)
    ->ArgsProduct({{1000, 100000}, {0, 1, 2, 3, 4}, {0, 1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);
BENCHMARK(BvhBuild)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
