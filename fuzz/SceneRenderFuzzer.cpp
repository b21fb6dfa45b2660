// libFuzzer harness: an .iv file rendered as a user renders it, on every path at once: read
// (loadScene), made ready to view (ViewSetup), drawn by `ivshadow render`'s default path, by
// every group traced (renderer TRACER), and by the exact reference. The SceneReaderFuzzer
// stops at the casters' extraction; the crashes issue 35 found lay further on (Embree's
// ray.valid() assertion in the traced picture and the reference, Coin's rendering of shapes
// the extraction had skipped). What fails here is a crash, a hang or a sanitizer report on any
// path; the pictures are also compared (TRACER against the reference: the same code), and a
// disagreement is printed, not stopped at, until the table of what each path may differ by
// (issue 36) says which are defects.
#include "fuzz/FuzzInput.h"
#include "headless/OffscreenRenderer.h"
#include "image/ImageComparison.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "raytrace/ReferenceRenderer.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "scene/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

constexpr int kWidth = 32, kHeight = 24;  // small: the paths, not the pixels, are under test

ivshadow::OffscreenRenderer& renderer() {
  static std::unique_ptr<ivshadow::OffscreenRenderer> made = [] {
    std::string error;
    auto created = ivshadow::OffscreenRenderer::create(kWidth, kHeight, error);
    if (!created) {
      std::fprintf(stderr, "SceneRenderFuzzer: no GL context: %s\n", error.c_str());
      std::exit(3);
    }
    return created;
  }();
  return *made;
}

void traceEveryGroup(SoNode* root) {
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i)
    static_cast<SoTransparentShadowGroup*>(paths[i]->getTail())
        ->renderer.setValue(SoTransparentShadowGroup::TRACER);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ivshadow::fuzz::initOnce();
  const std::string path = ivshadow::fuzz::writeInput(data, size, ".iv");
  ivshadow::LoadedScene scene;
  try {
    scene = ivshadow::loadScene(path);
  } catch (const ivshadow::InputError&) {
    return 0;  // refused with a message: what bad input should get
  }
  ivshadow::OffscreenRenderer& gl = renderer();
  const ivshadow::ViewSetup view =
      ivshadow::ViewSetup::prepare(scene.root.get(), SbViewportRegion(kWidth, kHeight));
  gl.render(view.root.get());
  traceEveryGroup(view.root.get());
  gl.render(view.root.get());
  const ivshadow::Image traced = gl.read();
  ivshadow::ReferenceOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.threads = 1;
  options.bounceSamples = 4;
  const auto reference = ivshadow::renderReference(view.root.get(), options);
  if (reference && std::getenv("IVSHADOW_FUZZ_ORACLE") != nullptr) {
    const ivshadow::ImageComparison comparison = ivshadow::ImageComparison::compare(
        reference->image.toImage(), traced, "reference", "TRACER");
    if (comparison.all.maxError > 8)
      std::fprintf(stderr, "SceneRenderFuzzer: TRACER and the reference differ by %d steps\n",
                   comparison.all.maxError);
  }
  return 0;
}
