#pragma once

#include "headless/OffscreenRenderer.h"
#include "image/ImageSize.h"

#include <iostream>
#include <memory>
#include <string>

namespace ivshadow {

// The headless renderer a command draws with; null after telling the user which EGL step
// failed (the command then exits 3).
inline std::unique_ptr<OffscreenRenderer> openRenderer(const ImageSize& size) {
  std::string error;
  std::unique_ptr<OffscreenRenderer> renderer =
      OffscreenRenderer::create(size.width, size.height, error);
  if (!renderer)
    std::cerr << "ivshadow: error: no GL context for headless rendering: " << error << '\n';
  return renderer;
}

}  // namespace ivshadow
