#pragma once

#include "callbacks/GlObject.h"
#include "ivshadow/Export.h"

namespace ivshadow {

// Release functors for the GL object kinds the passes own, and the owners built from them.
struct IVSHADOW_INTERNAL GlTextureRelease {
  void operator()(unsigned int name) const;
};
struct IVSHADOW_INTERNAL GlBufferRelease {
  void operator()(unsigned int name) const;
};
struct IVSHADOW_INTERNAL GlVertexArrayRelease {
  void operator()(unsigned int name) const;
};
struct IVSHADOW_INTERNAL GlProgramRelease {
  void operator()(unsigned int name) const;
};
struct IVSHADOW_INTERNAL GlFramebufferObjectRelease {
  void operator()(unsigned int name) const;
};
struct IVSHADOW_INTERNAL GlRenderbufferObjectRelease {
  void operator()(unsigned int name) const;
};

using GlTexture = GlObject<GlTextureRelease>;
using GlBuffer = GlObject<GlBufferRelease>;
using GlVertexArray = GlObject<GlVertexArrayRelease>;
using GlProgramObject = GlObject<GlProgramRelease>;
using GlFramebuffer = GlObject<GlFramebufferObjectRelease>;
using GlRenderbuffer = GlObject<GlRenderbufferObjectRelease>;

// Creators (DSA, GL 4.5): each returns a new owner of one object of the given kind.
IVSHADOW_INTERNAL GlTexture createTexture(unsigned int target);
IVSHADOW_INTERNAL GlBuffer createBuffer();
IVSHADOW_INTERNAL GlVertexArray createVertexArray();
IVSHADOW_INTERNAL GlFramebuffer createFramebuffer();
IVSHADOW_INTERNAL GlRenderbuffer createRenderbuffer();
// A 2D texture of one level and nearest sampling: a render target read by texel.
IVSHADOW_INTERNAL GlTexture createTarget2D(unsigned int format, int width, int height);
// A size x size 2D array texture of `layers` layers, one level, nearest sampling clamped to
// the edge: a map's layers, read by texel.
GlTexture createTargetArray(unsigned int format, int size, int layers);

}  // namespace ivshadow
