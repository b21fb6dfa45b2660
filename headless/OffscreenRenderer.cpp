#include "headless/OffscreenRenderer.h"

#include "gl/GlCapabilities.h"
#include "gl/GlFrame.h"
#include "gl/GlFramebufferTarget.h"
#include "gl/GlTimerQuery.h"
#include "headless/CoinOffscreenContexts.h"
#include "headless/EglHeadlessContext.h"
#include "scene_input/CoinMessageCapture.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/misc/SoContextHandler.h>

#include <chrono>
#include <optional>

namespace ivshadow {

// Member order matters: GL objects are released before the context that owns them.
struct OffscreenRenderer::Impl {
  std::unique_ptr<EglHeadlessContext> context;
  GlCapabilities capabilities;
  GlFramebufferTarget target;
  std::optional<GlTimerQuery> timer;
  std::unique_ptr<SoGLRenderAction> action;
  std::uint32_t cacheContext = 0;
};

std::unique_ptr<OffscreenRenderer> OffscreenRenderer::create(int width, int height,
                                                             std::string& error,
                                                             bool* outsideGlLimits) {
  installCoinOffscreenContexts();
  auto impl = std::make_unique<Impl>();
  impl->context = EglHeadlessContext::create(error);
  if (!impl->context) return nullptr;
  impl->capabilities = GlCapabilities::queryCurrent();
  if (!impl->capabilities.framebufferObjects) {
    error = "the GL context (" + impl->capabilities.version + ", " + impl->capabilities.renderer +
            ") has no framebuffer objects";
    return nullptr;
  }
  error = impl->capabilities.sizeProblem(width, height);
  if (!error.empty()) {
    error = std::to_string(width) + "x" + std::to_string(height) + " is too large: " + error;
    if (outsideGlLimits) *outsideGlLimits = true;
    return nullptr;
  }
  impl->target = GlFramebufferTarget::create(width, height, error);
  if (!impl->target) return nullptr;
  if (impl->capabilities.timerQueries) impl->timer.emplace();
  impl->cacheContext = SoGLCacheContextElement::getUniqueCacheContext();
  impl->action = std::make_unique<SoGLRenderAction>(
      SbViewportRegion(static_cast<short>(width), static_cast<short>(height)));
  impl->action->setCacheContext(impl->cacheContext);
  return std::unique_ptr<OffscreenRenderer>(new OffscreenRenderer(std::move(impl)));
}

OffscreenRenderer::OffscreenRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

OffscreenRenderer::~OffscreenRenderer() {
  // Coin frees the display lists, textures and programs it made for this context.
  impl_->context->makeCurrent();
  SoContextHandler::destructingContext(impl_->cacheContext);
}

OffscreenRenderer::FrameTiming OffscreenRenderer::render(SoNode* root) {
  return render([root](SoGLRenderAction& action) { action.apply(root); });
}

OffscreenRenderer::FrameTiming OffscreenRenderer::render(
    const std::function<void(SoGLRenderAction&)>& draw) {
  using Clock = std::chrono::steady_clock;
  impl_->context->makeCurrent();
  const auto start = Clock::now();
  impl_->target.bindAndClear(background_[0], background_[1], background_[2], 1.0f);
  {
    // Coin asks for a GLX context once per context to learn whether rendering is direct;
    // an EGL context has none, which is harmless, so that one warning is dropped.
    CoinMessageCapture capture;
    if (impl_->timer) impl_->timer->begin();
    draw(*impl_->action);
    if (impl_->timer) impl_->timer->end();
    waitForGpu();
    capture.forwardExcept("glxglue_isdirect");
  }
  FrameTiming timing;
  timing.wallMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  timing.gpuMs = impl_->timer ? impl_->timer->elapsedMs() : 0.0;
  return timing;
}

Image OffscreenRenderer::read() const {
  impl_->context->makeCurrent();
  return impl_->target.read();
}

SoGLRenderAction& OffscreenRenderer::action() {
  return *impl_->action;
}
const GlCapabilities& OffscreenRenderer::capabilities() const {
  return impl_->capabilities;
}
const std::string& OffscreenRenderer::platform() const {
  return impl_->context->platform();
}
int OffscreenRenderer::width() const {
  return impl_->target.width();
}
int OffscreenRenderer::height() const {
  return impl_->target.height();
}

}  // namespace ivshadow
