#pragma once

#include "headless/OffscreenRenderer.h"
#include "image_files/ImageSize.h"
#include "scene/InputError.h"

#include <iostream>
#include <memory>
#include <string>

namespace ivshadow {

// The headless renderer a command draws with; null after telling the user which EGL step
// failed (the command then exits 3). A size beyond the GL limits is bad input: it throws
// InputError naming --size and the limit (exit 2), before any buffer is allocated.
inline std::unique_ptr<OffscreenRenderer> openRenderer(const ImageSize& size) {
  std::string error;
  bool outsideGlLimits = false;
  std::unique_ptr<OffscreenRenderer> renderer =
      OffscreenRenderer::create(size.width, size.height, error, &outsideGlLimits);
  if (outsideGlLimits) throw InputError("--size " + size.toString() + ": error: " + error);
  if (!renderer)
    std::cerr << "ivshadow: error: no GL context for headless rendering: " << error << '\n';
  return renderer;
}

}  // namespace ivshadow
