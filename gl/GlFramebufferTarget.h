#pragma once

#include "gl/GlHandles.h"
#include "image/Image.h"
#include "ivshadow/Export.h"

#include <string>

namespace ivshadow {

// An off-screen render target: RGBA8 colour plus a 24-bit depth / 8-bit stencil buffer.
class IVSHADOW_INTERNAL GlFramebufferTarget {
 public:
  // Builds the target in the current context; on failure returns an empty target and says
  // why in `error`.
  static GlFramebufferTarget create(int width, int height, std::string& error);

  GlFramebufferTarget() = default;
  explicit operator bool() const { return static_cast<bool>(framebuffer_); }
  int width() const { return width_; }
  int height() const { return height_; }

  // Binds the target for drawing and reading, sets the viewport, clears it and enables depth
  // testing, as Coin expects of whoever applies a SoGLRenderAction.
  void bindAndClear(float red, float green, float blue, float alpha);
  Image read() const;

 private:
  int width_ = 0;
  int height_ = 0;
  GlFramebuffer framebuffer_;
  GlRenderbuffer colour_;
  GlRenderbuffer depthStencil_;
};

}  // namespace ivshadow
