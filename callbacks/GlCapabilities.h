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

  // Reads the capabilities of the context that is current on this thread.
  static GlCapabilities queryCurrent();

  // True for Mesa's llvmpipe/softpipe/swrast and other CPU rasterisers.
  bool isSoftwareRenderer() const;
};

}  // namespace ivshadow
