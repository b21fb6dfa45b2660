#pragma once

#include "image/Image.h"
#include "ivshadow/Export.h"

namespace ivshadow {

// Reads the lower-left width x height pixels of the current read framebuffer (for a
// double-buffered window, the back buffer before the swap) as RGBA8, rows top to bottom.
// Pixel-store state is saved and restored around the read.
IVSHADOW_INTERNAL Image captureReadFramebuffer(int width, int height);

// Blocks until the GL has finished all submitted work, so wall-clock time covers it.
IVSHADOW_INTERNAL void waitForGpu();

}  // namespace ivshadow
