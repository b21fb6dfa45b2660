#pragma once

#include "ivshadow/Export.h"

namespace ivshadow {

// The internal formats of a framebuffer's buffers, as a single-sampled copy must have them to
// be the source or the target of a blit (GL asks depth formats to match, and a copy between
// equal formats is a plain copy). GL_NONE (0) where the framebuffer has no such buffer or
// names no format this can tell. `framebuffer` 0 is the default framebuffer.
IVSHADOW_INTERNAL unsigned int depthFormat(unsigned int framebuffer);
// Of its colour buffer `readBuffer` (GL_COLOR_ATTACHMENTi, or GL_BACK, GL_FRONT, ... of the
// default framebuffer).
IVSHADOW_INTERNAL unsigned int colourFormat(unsigned int framebuffer, unsigned int readBuffer);

// How glReadPixels returns a buffer of one of these formats unconverted: the format and type
// to ask for and the bytes a pixel takes; {0, 0, 0} for a format without such a read.
struct PixelTransfer {
  unsigned int format = 0;
  unsigned int type = 0;
  int bytes = 0;
};
IVSHADOW_INTERNAL PixelTransfer depthTransfer(unsigned int depthFormat);
// How a colour buffer of `colourFormat` is read with every bit it stores (a driver's preferred
// read of a 10-bit or 565 buffer may be 8 bits a channel, which would lose some).
IVSHADOW_INTERNAL PixelTransfer colourTransfer(unsigned int colourFormat);

}  // namespace ivshadow
