#include "tests/gl/CheckedRenderer.h"

#include <gtest/gtest.h>

namespace ivshadow::test {

std::unique_ptr<CheckedRenderer> CheckedRenderer::create(int width, int height, std::string& error,
                                                         bool* outsideGlLimits) {
  std::unique_ptr<CheckedRenderer> checked(new CheckedRenderer);
  checked->renderer_ = OffscreenRenderer::create(width, height, error, outsideGlLimits);
  if (!checked->renderer_) return nullptr;
  // The new context is current: what it reports from here on is the test's doing.
  checked->errors_ = std::make_unique<GlDebugErrors>();
  return checked;
}

CheckedRenderer::~CheckedRenderer() {
  if (!renderer_) return;
  renderer_.reset();
  // Only what KHR_debug reported: the context is gone, and glGetError would read another.
  const std::string errors = errors_->take(false);
  if (!errors.empty()) ADD_FAILURE() << "GL errors while the renderer was destroyed:" << errors;
}

OffscreenRenderer::FrameTiming CheckedRenderer::render(SoNode* root) {
  expectNoEarlierErrors();
  const OffscreenRenderer::FrameTiming timing = renderer_->render(root);
  expectNoGlErrors("in the frame");
  return timing;
}

OffscreenRenderer::FrameTiming CheckedRenderer::render(
    const std::function<void(SoGLRenderAction&)>& draw) {
  expectNoEarlierErrors();
  const OffscreenRenderer::FrameTiming timing = renderer_->render(draw);
  expectNoGlErrors("in the frame");
  return timing;
}

Image CheckedRenderer::read() const {
  Image image = renderer_->read();
  expectNoGlErrors("reading the frame");
  return image;
}

void CheckedRenderer::expectNoEarlierErrors() const {
  // Another context may be current: only KHR_debug's reports are this context's.
  const std::string errors = errors_->take(false);
  if (!errors.empty()) ADD_FAILURE() << "GL errors since the last frame:" << errors;
}

void CheckedRenderer::expectNoGlErrors(const char* when) const {
  const std::string errors = errors_->take(true);
  if (!errors.empty()) ADD_FAILURE() << "GL errors " << when << ":" << errors;
}

}  // namespace ivshadow::test
