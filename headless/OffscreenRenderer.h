#pragma once

#include "image/Image.h"

#include <Inventor/SbColor.h>

#include <functional>
#include <memory>
#include <string>

class SoGLRenderAction;
class SoNode;

namespace ivshadow {

struct GlCapabilities;

// Renders Coin scene graphs without a window: an EGL context, an off-screen framebuffer and a
// SoGLRenderAction applied directly (Coin's SoOffscreenRenderer cannot make a context on
// Mesa/Xvfb machines). Also measures each frame's wall-clock and GPU time.
class OffscreenRenderer {
 public:
  struct FrameTiming {
    double wallMs = 0.0;  // submission to completion (glFinish), as the user waits for it
    // GL_TIME_ELAPSED of the traversal; 0 without timer queries. Mesa llvmpipe rasterises
    // when work is flushed, after the query has ended, so there it is far below wallMs.
    double gpuMs = 0.0;
  };

  // Null with the reason in `error` when no context or render target can be made. A size
  // beyond the context's GL limits (GlCapabilities::sizeProblem) is refused before anything
  // is allocated, and sets `*outsideGlLimits` when given: that is the caller's bad input.
  static std::unique_ptr<OffscreenRenderer> create(int width, int height, std::string& error,
                                                   bool* outsideGlLimits = nullptr);
  ~OffscreenRenderer();

  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  void setBackground(const SbColor& colour) { background_ = colour; }
  FrameTiming render(SoNode* root);
  // The same frame, drawing through `draw` (given the action, in the bound and cleared
  // target) instead of applying the action to one root.
  FrameTiming render(const std::function<void(SoGLRenderAction&)>& draw);
  Image read() const;

  SoGLRenderAction& action();
  const GlCapabilities& capabilities() const;
  // The EGL platform the context lives on ("surfaceless", "device", ...).
  const std::string& platform() const;
  int width() const;
  int height() const;

 private:
  struct Impl;
  explicit OffscreenRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  SbColor background_{0.0f, 0.0f, 0.0f};
};

}  // namespace ivshadow
