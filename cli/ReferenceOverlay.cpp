#include "cli/ReferenceOverlay.h"

#include "gl/TracedPicturePass.h"
#include "headless/OffscreenRenderer.h"
#include "nodes/TracerActivity.h"
#include "reference/ReferenceRenderer.h"
#include "scene_input/CoinMessageCapture.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoNode.h>

#include <cmath>
#include <cstdint>

namespace ivshadow {

std::string drawUntracedOver(SoNode* root, const SbColor& background, ReferenceResult& result) {
  // The traced picture is not needed past here: its 20 bytes a pixel go before the picture is
  // written (the reference's memory budget counts on it).
  struct Release {
    ReferenceResult& result;
    ~Release() {
      std::vector<float>().swap(result.tracedRgba);
      std::vector<float>().swap(result.tracedDepth);
    }
  } release{result};
  if (result.untracedPaths.empty() || result.tracedRgba.empty()) return {};
  FloatImage& image = result.image;
  std::string error;
  std::unique_ptr<OffscreenRenderer> renderer =
      OffscreenRenderer::create(image.width, image.height, error);
  if (!renderer) return "no GL context to draw them: " + error;
  renderer->setBackground(background);
  // The reference has named each of these shapes; the group's own word on them, as GL draws
  // them through it again, would say it twice.
  CoinMessageCapture messages;
  renderer->render([&](SoGLRenderAction& action) {
    std::unique_ptr<TracedPicturePass> pass = TracedPicturePass::create(error);
    if (!pass) return;
    error = pass->upload(image.width, image.height, result.tracedRgba.data(),
                         result.tracedDepth.data());
    if (!error.empty()) return;
    pass->draw({0, 0, image.width, image.height}, {0, 0, image.width, image.height});
    SoPathList paths;
    for (const std::vector<int>& indices : result.untracedPaths) {
      auto* path = new SoPath(root);
      for (std::size_t i = 1; i < indices.size(); ++i) path->append(indices[i]);
      paths.append(path);
    }
    // Every group on the way draws as a plain separator, as under renderer TRACER.
    const TracerActivity::Scope drawing(TracerActivity::DrawingUntraced);
    action.apply(paths, FALSE);
  });
  messages.forwardExcept("which cast no shadow");
  if (!error.empty()) return error;
  const Image drawn = renderer->read();
  const Image traced = image.toImage();
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* gl = drawn.pixel(x, y);
      const std::uint8_t* own = traced.pixel(x, y);
      if (gl[0] == own[0] && gl[1] == own[1] && gl[2] == own[2]) continue;
      float* out = &image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3];
      for (int c = 0; c < 3; ++c) out[c] = float(gl[c]) / 255.0f;
    }
  return {};
}

}  // namespace ivshadow
