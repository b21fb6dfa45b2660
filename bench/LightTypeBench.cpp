// The cost of a spot and of a directional light against a point light in a shadow group, per
// method: the 100k-triangle sphere field (BenchScenes.h) with its deep shadow light replaced by
// an ordinary PointLight, SpotLight or DirectionalLight casting with the group's fields, the
// light moving every frame (the map rebuilt, or the rays traced again). Run:
// build/bin/ivshadow_bench --benchmark_filter=LightTypeFrame. Wall clock, GPU finished.
#include "BenchScenes.h"
#include "headless/OffscreenRenderer.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/ShadowMethod.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSpotLight.h>

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

namespace {

enum Kind { Point = 0, Spot = 1, Directional = 2 };

const char* kindName(int kind) {
  return kind == Point ? "point" : kind == Spot ? "spot" : "directional";
}

// Args: kind, method (MAP 1 / RAYS 2). 640 x 480.
void LightTypeFrame(benchmark::State& state) {
  ivshadow::init();
  std::string error;
  auto renderer = ivshadow::OffscreenRenderer::create(640, 480, error);
  if (!renderer) {
    state.SkipWithError(error.c_str());
    return;
  }
  SoSeparator* root = ivshadow::bench::sphereField(
      100000, true, ivshadow::bench::Shadows::DeepShadowGroup, 640, 480);
  SoSearchAction search;
  search.setType(SoDeepShadowLight::getClassTypeId());
  search.apply(root);
  SoPath* path = search.getPath();
  auto* lamp = static_cast<SoDeepShadowLight*>(path->getTail());
  auto* group = static_cast<SoTransparentShadowGroup*>(path->getNodeFromTail(1));
  group->method = int(state.range(1));
  const SbVec3f at = lamp->location.getValue();
  const int kind = int(state.range(0));
  SoLight* light = nullptr;
  if (kind == Point) {
    auto* point = new SoPointLight;
    point->location = at;
    light = point;
  } else if (kind == Spot) {
    auto* spot = new SoSpotLight;
    spot->location = at;
    spot->direction.setValue(-at);
    spot->cutOffAngle = 1.0f;  // covers the field of spheres
    light = spot;
  } else {
    auto* directional = new SoDirectionalLight;
    directional->direction.setValue(-at);
    light = directional;
  }
  group->replaceChild(lamp, light);
  renderer->render(root);  // programs, the casters, the first map or trace
  int frame = 0;
  for (auto _ : state) {
    // A small move every frame: the map is built, or the rays traced, again.
    const SbVec3f moved = at + SbVec3f(0.05f * float(++frame % 7), 0.0f, 0.0f);
    if (kind == Directional)
      static_cast<SoDirectionalLight*>(light)->direction.setValue(-moved);
    else if (kind == Spot)
      static_cast<SoSpotLight*>(light)->location.setValue(moved);
    else
      static_cast<SoPointLight*>(light)->location.setValue(moved);
    state.SetIterationTime(renderer->render(root).wallMs * 1e-3);
  }
  state.SetLabel(std::string(kindName(kind)) + " " +
                 ivshadow::shadowMethodName(ivshadow::ShadowMethod(state.range(1))));
  renderer.reset();
  root->unref();
}

BENCHMARK(LightTypeFrame)
    ->ArgsProduct({{Point, Spot, Directional},
                   {int(SoDeepShadowLight::MAP), int(SoDeepShadowLight::RAYS)}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

}  // namespace
