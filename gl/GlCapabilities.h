#pragma once

#include "ivshadow/Export.h"

#include <string>

namespace ivshadow {

// What the current GL context offers, read once per context right after it is made current.
struct IVSHADOW_INTERNAL GlCapabilities {
  std::string version;
  std::string renderer;
  std::string vendor;
  int major = 0;
  int minor = 0;
  bool compatibilityProfile = false;
  bool framebufferObjects = false;
  bool timerQueries = false;
  // The largest render target, texture and viewport side (GL_MAX_RENDERBUFFER_SIZE,
  // GL_MAX_TEXTURE_SIZE, GL_MAX_VIEWPORT_DIMS): the frame, the peeling and capture textures
  // and the viewport are all as large as the image.
  int maxRenderbufferSize = 0;
  int maxTextureSize = 0;
  int maxViewportWidth = 0;
  int maxViewportHeight = 0;

  // Reads the capabilities of the context that is current on this thread.
  static GlCapabilities queryCurrent();

  // Empty when a width x height image fits every limit above; else which limit it exceeds,
  // e.g. "GL_MAX_TEXTURE_SIZE of this GL (llvmpipe ...) is 16384 pixels per side".
  std::string sizeProblem(int width, int height) const;

  // True for Mesa's llvmpipe/softpipe/swrast and other CPU rasterisers.
  bool isSoftwareRenderer() const;
};

}  // namespace ivshadow
