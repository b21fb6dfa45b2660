// Order-independent transparency cost and error against depth complexity: the plugin's
// SoPeelingSeparator (DUAL, FRONT_TO_BACK, FRAGMENT_LISTS, and TRACER still and with the
// camera moving) and a group with renderer TRACER (still, with the camera moving, and moving
// with movingResolution 0.5) against Coin's
// SORTED_LAYERS_BLEND with as many passes as there are layers and with its default 4, and
// plain BLEND. Run:
// build/bin/ivshadow_bench
// --benchmark_filter=Peel. Times are wall clock per frame, GPU finished; `max_error` is the
// largest channel error (0..255) against the exact CPU compositing of tests/gl/PeelReference.
#include "headless/OffscreenRenderer.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/PeelStatistics.h"
#include "tests/gl/PeelReference.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>

namespace {

constexpr int kSize = 400;
constexpr double kViewHeight = 2.4;

// kTraced: a SoTransparentShadowGroup with renderer TRACER (the stack traced on the CPU);
// kTracedMoving: the same with the camera moving every frame, so that every frame traces (in
// full: movingResolution 1, where the default reduces a motion's frames);
// kTracedReduced: moving, with movingResolution 0.5 (every frame after the first traced at
// 200 x 200 and stretched), its error that of the refined still frame. kSeparatorTraced and
// kSeparatorTracedMoving: a SoPeelingSeparator with method TRACER, still and moving.
enum Method {
  kBlend,
  kSortedLayers,
  kDual,
  kFrontToBack,
  kFragmentLists,
  kTraced,
  kTracedMoving,
  kTracedReduced,
  kSeparatorTraced,
  kSeparatorTracedMoving,
  kSortedLayersFour  // Coin's SORTED_LAYERS_BLEND with its default 4 passes, whatever the depth
};

bool traced(Method method) {
  return method == kTraced || method == kTracedMoving || method == kTracedReduced;
}
bool moving(Method method) {
  return method == kTracedMoving || method == kTracedReduced || method == kSeparatorTracedMoving;
}

// `depth` coloured glass sheets stacked over an opaque floor, each tilted so that it cuts
// its neighbours: every pixel of the centre sees `depth` transparent layers, in an order that
// changes across the picture. Drawn in a shuffled order so that traversal order is wrong.
std::string stackText(int depth, Method method) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height " << kViewHeight
     << " }\nLightModel { model BASE_COLOR }\n"
     << (method == kDual            ? "PeelingSeparator { method DUAL\n"
         : method == kFrontToBack   ? "PeelingSeparator { method FRONT_TO_BACK\n"
         : method == kFragmentLists ? "PeelingSeparator { method FRAGMENT_LISTS\n"
         : method == kSeparatorTraced || method == kSeparatorTracedMoving
             ? "PeelingSeparator { method TRACER\n"
         : method == kTracedReduced
             ? "TransparentShadowGroup { renderer TRACER movingResolution 0.5\n"
         : traced(method) ? "TransparentShadowGroup { renderer TRACER movingResolution 1\n"
                          : "Separator {\n")
     << "BaseColor { rgb 0.5 0.5 0.5 }\n"
     << "Coordinate3 { point [ -1.1 -1.1 -2, 1.1 -1.1 -2, 1.1 1.1 -2, -1.1 1.1 -2 ] }\n"
     << "FaceSet { numVertices 4 }\n";
  for (int k = 0; k < depth; ++k) {
    const int i = (k * 7) % depth;  // shuffled
    const double z = -1.0 + 2.0 * (i + 0.5) / depth;
    const double slope = 0.9 / depth * ((i % 2) ? 1.0 : -1.0);
    const double r = 0.5 + 0.5 * std::sin(i * 1.3), g = 0.5 + 0.5 * std::sin(i * 2.1 + 1),
                 b = 0.5 + 0.5 * std::sin(i * 0.7 + 2);
    iv << "Separator { Material { diffuseColor " << r << ' ' << g << ' ' << b
       << " transparency 0.6 }\n"
       << "Coordinate3 { point [ -1 -1 " << z - slope << ", 1 -1 " << z - slope << ", 1 1 "
       << z + slope << ", -1 1 " << z + slope << " ] }\n"
       << "IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ] } }\n";
  }
  iv << "}\n}\n";
  return iv.str();
}

SoSeparator* read(const std::string& text) {
  SoInput input;
  input.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&input);
  root->ref();
  return root;
}

// Args: method, depth complexity.
void Peel(benchmark::State& state) {
  ivshadow::init();
  const auto method = Method(state.range(0));
  const int depth = int(state.range(1));
  std::string error;
  auto renderer = ivshadow::OffscreenRenderer::create(kSize, kSize, error);
  if (!renderer) {
    state.SkipWithError(error.c_str());
    return;
  }
  if (method == kSortedLayers || method == kSortedLayersFour) {
    renderer->action().setTransparencyType(SoGLRenderAction::SORTED_LAYERS_BLEND);
    renderer->action().setSortedLayersNumPasses(method == kSortedLayers ? depth : 4);
  }
  const std::string text = stackText(depth, method);
  SoSeparator* root = read(text);
  renderer->render(root);
  auto* camera = static_cast<SoCamera*>(root->getChild(0));
  const SbVec3f eye = camera->position.getValue();
  int frame = 0;
  for (auto _ : state) {
    if (moving(method))
      camera->position.setValue(eye + SbVec3f(0.01f * float(++frame % 2), 0.0f, 0.0f));
    state.SetIterationTime(renderer->render(root).wallMs * 1e-3);
  }
  // A traced frame's own share: the trace and its upload (the rest is Coin's traversal and
  // the picture's draw).
  if (traced(method))
    state.counters["trace_ms"] = ivshadow::collectDeepShadowStatistics(root).tracerMs;
  if (method == kSeparatorTraced || method == kSeparatorTracedMoving)
    state.counters["traced_frames"] = ivshadow::collectPeelStatistics(root).tracedFrames;
  const bool moves = moving(method);
  // The last timed frame may have ended where the camera began (an even count): moved off
  // once more, so that the frame back at the start is a moving one.
  if (moves && camera->position.getValue() == eye) {
    camera->position.setValue(eye + SbVec3f(0.01f, 0.0f, 0.0f));
    renderer->render(root);
  }
  camera->position.setValue(eye);
  const ivshadow::test::PeelReference reference(root, kViewHeight, kSize);
  const auto largestError = [&] {
    const ivshadow::Image image = renderer->read();
    double worst = 0.0;
    for (int y = 0; y < kSize; y += 4)
      for (int x = 0; x < kSize; x += 4)
        if (const auto expected = reference.pixel(x, y))
          for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(image.pixel(x, y)[c] - (*expected)[std::size_t(c)]));
    return worst;
  };
  if (moves) {
    renderer->render(root);
    // Reduced: that frame was a moving one (the camera moved back); the next, which finds
    // nothing changed, traces the full picture.
    if (method == kTracedReduced) {
      state.counters["moving_max_error"] = largestError();
      renderer->render(root);
    }
  }
  state.counters["max_error"] = largestError();
  state.SetLabel(method == kBlend             ? "BLEND"
                 : method == kSortedLayers    ? "SORTED_LAYERS_BLEND"
                 : method == kDual            ? "PeelingSeparator DUAL"
                 : method == kFrontToBack     ? "PeelingSeparator FRONT_TO_BACK"
                 : method == kFragmentLists   ? "PeelingSeparator FRAGMENT_LISTS"
                 : method == kTraced          ? "TRACER still"
                 : method == kTracedMoving    ? "TRACER camera moving"
                 : method == kTracedReduced   ? "TRACER camera moving, movingResolution 0.5"
                 : method == kSeparatorTraced       ? "PeelingSeparator TRACER still"
                 : method == kSeparatorTracedMoving ? "PeelingSeparator TRACER camera moving"
                                                    : "SORTED_LAYERS_BLEND, 4 passes");
  renderer.reset();
  root->unref();
}

void depths(benchmark::internal::Benchmark* b) {
  for (int method : {kBlend, kSortedLayers, kDual, kFrontToBack, kFragmentLists, kTraced,
                     kTracedMoving, kTracedReduced, kSeparatorTraced, kSeparatorTracedMoving,
                     kSortedLayersFour})
    for (int depth : {1, 2, 4, 8, 16}) b->Args({method, depth});
  b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(5);
}
BENCHMARK(Peel)->Apply(depths);

}  // namespace
