#pragma once

#include "gl/GlObject.h"
#include "ivshadow/Export.h"

#include <string>

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

// Names for a GPU debugger (RenderDoc, apitrace, Nsight): the passes' GL objects labelled and
// their commands grouped, through KHR_debug. Where the current context lacks KHR_debug (core
// from OpenGL 4.3; the passes need 4.5, so only a context that draws no pass lacks it) both do
// nothing.

// Labels GL object `name` of kind `identifier` (GL_TEXTURE, GL_FRAMEBUFFER, GL_BUFFER,
// GL_PROGRAM, GL_VERTEX_ARRAY, ...) "ivshadow <label>".
IVSHADOW_INTERNAL void labelGlObject(unsigned int identifier, unsigned int name,
                                     const std::string& label);

// The GL commands issued while it lives, grouped as "ivshadow <name>" (glPushDebugGroup and
// glPopDebugGroup): a debugger shows each pass as one node of the frame. Made and destroyed
// with the same context current, nested like any scope.
class IVSHADOW_INTERNAL GlDebugGroup {
 public:
  explicit GlDebugGroup(const std::string& name);
  ~GlDebugGroup();
  GlDebugGroup(const GlDebugGroup&) = delete;
  GlDebugGroup& operator=(const GlDebugGroup&) = delete;

 private:
  bool pushed_ = false;
};

}  // namespace ivshadow
