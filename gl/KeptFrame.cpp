#include "gl/KeptFrame.h"

#include "gl/FramebufferFormats.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlStateScope.h"
#include "gl/PixelStoreScope.h"

#include <epoxy/gl.h>

#include <cstddef>

namespace ivshadow {
namespace {

// The bytes of `rows` rows of `width` pixels of `bytes` each, as glReadPixels packs them at
// PixelStoreScope's alignment of 4.
std::size_t packedSize(int width, int rows, int bytes) {
  const std::size_t row = (std::size_t(width) * std::size_t(bytes) + 3) / 4 * 4;
  return row * std::size_t(rows);
}

bool hasStencil(GLenum depthFormat) {
  return depthFormat == GL_DEPTH24_STENCIL8 || depthFormat == GL_DEPTH32F_STENCIL8;
}

// The colour buffer the framebuffer bound for drawing reads, when it draws into that one
// buffer alone (every other draw buffer GL_NONE: a blit writes them all) with every channel
// writable (then it is what the picture changed, and a blit
// into it changes nothing a draw would not); else GL_NONE. The framebuffer must be bound for
// reading too.
GLenum drawnAndRead() {
  GLint readBuffer = GL_NONE, first = GL_NONE, buffers = 1;
  glGetIntegerv(GL_READ_BUFFER, &readBuffer);
  glGetIntegerv(GL_DRAW_BUFFER0, &first);
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &buffers);
  bool one = first == readBuffer;
  for (GLint i = 1; i < buffers && one; ++i) {
    GLint other = GL_NONE;
    glGetIntegerv(GLenum(GL_DRAW_BUFFER0 + i), &other);
    one = other == GL_NONE;
  }
  GLboolean mask[4] = {GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE};
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  return one && mask[0] && mask[1] && mask[2] && mask[3] ? GLenum(readBuffer) : GLenum(GL_NONE);
}

}  // namespace

bool KeptFrame::readBefore(const std::array<int, 4>& viewport) {
  readable_ = false;
  GlStateScope scope(GlStateScope::kFramebuffers);
  const auto drawn = GLuint(scope.drawFramebuffer());
  GLint samples = 0;
  glGetNamedFramebufferParameteriv(drawn, GL_SAMPLES, &samples);
  if (samples != 0) return false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, drawn);
  const GLenum buffer = drawnAndRead();
  if (buffer == GL_NONE) return false;
  layout_.viewport = viewport;
  layout_.colourFormat = colourFormat(drawn, buffer);
  layout_.depthFormat = depthFormat(drawn);
  const PixelTransfer depth = depthTransfer(layout_.depthFormat);
  if (layout_.colourFormat == GL_NONE || depth.bytes == 0) return false;
  const PixelTransfer colour = colourTransfer(layout_.colourFormat);
  if (colour.bytes == 0) return false;
  PixelStoreScope store;
  now_.colour.resize(packedSize(viewport[2], viewport[3], colour.bytes));
  now_.depth.resize(packedSize(viewport[2], viewport[3], depth.bytes));
  glReadPixels(viewport[0], viewport[1], viewport[2], viewport[3], colour.format, colour.type,
               now_.colour.data());
  glReadPixels(viewport[0], viewport[1], viewport[2], viewport[3], depth.format, depth.type,
               now_.depth.data());
  readable_ = true;
  depthAsTraced_ = now_.depth == tracedDepth_;
  return true;
}

bool KeptFrame::depthAsTraced() const {
  return readable_ && depthAsTraced_;
}

void KeptFrame::markTraced() {
  if (readable_)
    tracedDepth_ = now_.depth;
  else
    tracedDepth_.clear();
  depthAsTraced_ = readable_;
  forget();
}

void KeptFrame::forget() {
  valid_ = false;
}

bool KeptFrame::restore() {
  if (!readable_ || !valid_ || !(layout_ == keptLayout_)) return false;
  // Two depths equal to the one traced at are equal without a second comparison.
  const bool sameDepth = (depthAsTraced_ && keptAtTracedDepth_) || now_.depth == keptBefore_.depth;
  if (!sameDepth || now_.colour != keptBefore_.colour) return false;
  GlStateScope scope(GlStateScope::kFramebuffers);
  blit(framebuffer_.get(), GLuint(scope.drawFramebuffer()), false);
  return true;
}

void KeptFrame::keep() {
  valid_ = false;
  if (!readable_) return;
  const std::array<int, 4>& viewport = layout_.viewport;
  if (!(layout_ == keptLayout_) || !framebuffer_) {
    // A layout GL could not hold is not tried again every frame.
    if (failedLayout_ && *failedLayout_ == layout_) return;
    framebuffer_ = GlFramebuffer();
    clearGlErrors();
    colour_ = createRenderbuffer();
    glNamedRenderbufferStorage(colour_.get(), layout_.colourFormat, viewport[2], viewport[3]);
    depth_ = createRenderbuffer();
    glNamedRenderbufferStorage(depth_.get(), layout_.depthFormat, viewport[2], viewport[3]);
    if (!glAllocationError(GlAllocation::Framebuffer).empty()) return giveUp();
    GlFramebuffer framebuffer = createFramebuffer();
    glNamedFramebufferRenderbuffer(framebuffer.get(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                   colour_.get());
    glNamedFramebufferRenderbuffer(
        framebuffer.get(),
        hasStencil(layout_.depthFormat) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
        GL_RENDERBUFFER, depth_.get());
    if (!framebufferIncompleteness(framebuffer.get()).empty()) return giveUp();
    framebuffer_ = std::move(framebuffer);
    keptLayout_ = layout_;
  }
  GlStateScope scope(GlStateScope::kFramebuffers);
  blit(GLuint(scope.drawFramebuffer()), framebuffer_.get(), true);
  keptBefore_ = now_;
  keptAtTracedDepth_ = depthAsTraced_;
  valid_ = true;
}

void KeptFrame::giveUp() {
  colour_ = GlRenderbuffer();
  depth_ = GlRenderbuffer();
  failedLayout_ = layout_;
}

void KeptFrame::blit(unsigned int from, unsigned int to, bool toKept) const {
  // A blit is clipped by the scissor test an application may have left on.
  GlStateScope tests(GlStateScope::kFragmentTests);
  tests.disableFragmentTests();
  const std::array<int, 4>& v = layout_.viewport;
  const std::array<int, 4> drawn{v[0], v[1], v[0] + v[2], v[1] + v[3]};
  const std::array<int, 4> kept{0, 0, v[2], v[3]};
  const std::array<int, 4>& source = toKept ? drawn : kept;
  const std::array<int, 4>& target = toKept ? kept : drawn;
  GLbitfield mask = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT;
  // Depth and stencil together: a packed buffer is then one plain copy (its stencil is what
  // readBefore() compared, so the kept one is this frame's).
  if (hasStencil(keptLayout_.depthFormat)) mask |= GL_STENCIL_BUFFER_BIT;
  glBlitNamedFramebuffer(from, to, source[0], source[1], source[2], source[3], target[0], target[1],
                         target[2], target[3], mask, GL_NEAREST);
}

}  // namespace ivshadow
