#pragma once

#include "headless/OffscreenRenderer.h"
#include "tests/gl/GlDebugErrors.h"

#include <functional>
#include <memory>
#include <string>

namespace ivshadow::test {

// The headless renderer as the tests use it: OffscreenRenderer's calls, and every frame
// checked for GL errors (GlDebugErrors). A frame, or the GL calls a test made on the context
// since the last frame, that GL reported as an error fails the current test, naming each
// error; so does an error while the renderer is destroyed (Coin freeing what it made for the
// context). Every in-process render of the GL tests goes through one of these.
class CheckedRenderer {
 public:
  // As OffscreenRenderer::create.
  static std::unique_ptr<CheckedRenderer> create(int width, int height, std::string& error,
                                                 bool* outsideGlLimits = nullptr);
  ~CheckedRenderer();
  CheckedRenderer(const CheckedRenderer&) = delete;
  CheckedRenderer& operator=(const CheckedRenderer&) = delete;

  void setBackground(const SbColor& colour) { renderer_->setBackground(colour); }
  OffscreenRenderer::FrameTiming render(SoNode* root);
  OffscreenRenderer::FrameTiming render(const std::function<void(SoGLRenderAction&)>& draw);
  Image read() const;

  SoGLRenderAction& action() { return renderer_->action(); }
  const GlCapabilities& capabilities() const { return renderer_->capabilities(); }
  const std::string& platform() const { return renderer_->platform(); }
  int width() const { return renderer_->width(); }
  int height() const { return renderer_->height(); }

  // Fails the current test (once) when GL reported errors on this context since the last
  // check, and forgets them. The context must be current (it is after render() and read()).
  void expectNoGlErrors(const char* when) const;

 private:
  CheckedRenderer() = default;
  // The errors of the test's own calls since the last check, told apart from the frame's.
  void expectNoEarlierErrors() const;

  // Declared first: the context (in renderer_) reports into it until it is destroyed.
  std::unique_ptr<GlDebugErrors> errors_;
  std::unique_ptr<OffscreenRenderer> renderer_;
};

}  // namespace ivshadow::test
