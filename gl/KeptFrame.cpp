#include "gl/KeptFrame.h"

#include "gl/FramebufferFormats.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlStateScope.h"
#include "gl/PixelStoreScope.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <utility>

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

bool KeptFrame::readBefore(const std::array<int, 4>& viewport, const std::array<int, 4>& region) {
  readable_ = false;
  colourRead_ = false;
  depthRead_ = false;
  GlStateScope scope(GlStateScope::kFramebuffers);
  const auto drawn = GLuint(scope.drawFramebuffer());
  GLint samples = 0;
  glGetNamedFramebufferParameteriv(drawn, GL_SAMPLES, &samples);
  if (samples != 0) return false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, drawn);
  const GLenum buffer = drawnAndRead();
  if (buffer == GL_NONE) return false;
  layout_.viewport = viewport;
  region_ = {std::clamp(region[0], 0, viewport[2]), std::clamp(region[1], 0, viewport[3]),
             std::clamp(region[2], 0, viewport[2]), std::clamp(region[3], 0, viewport[3])};
  region_[2] = std::max(region_[2], region_[0]);
  region_[3] = std::max(region_[3], region_[1]);
  layout_.colourFormat = colourFormat(drawn, buffer);
  layout_.depthFormat = depthFormat(drawn);
  if (layout_.colourFormat == GL_NONE || depthTransfer(layout_.depthFormat).bytes == 0 ||
      colourTransfer(layout_.colourFormat).bytes == 0)
    return false;
  readable_ = true;
  // The same bytes over the same pixels of the same kind of buffer.
  depthAsTraced_ = tracedLayout_ == layout_ && tracedRegion_ == region_ &&
                   equalsFramebuffer(Buffer::Depth, tracedDepth_);
  if (!depthAsTraced_) read(Buffer::Depth);
  return true;
}

PixelTransfer KeptFrame::transfer(Buffer buffer) const {
  return buffer == Buffer::Colour ? colourTransfer(layout_.colourFormat)
                                  : depthTransfer(layout_.depthFormat);
}

void KeptFrame::readRows(Buffer buffer, int first, int rows, unsigned char* into) const {
  GlStateScope scope(GlStateScope::kFramebuffers);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(scope.drawFramebuffer()));
  PixelStoreScope store;
  const PixelTransfer pixels = transfer(buffer);
  const std::array<int, 4>& v = layout_.viewport;
  glReadPixels(v[0] + region_[0], v[1] + region_[1] + first, width(), rows, pixels.format,
               pixels.type, into);
}

void KeptFrame::read(Buffer buffer) {
  std::vector<unsigned char>& into = buffer == Buffer::Colour ? now_.colour : now_.depth;
  into.resize(packedSize(width(), height(), transfer(buffer).bytes));
  if (!into.empty()) readRows(buffer, 0, height(), into.data());
  (buffer == Buffer::Colour ? colourRead_ : depthRead_) = true;
}

bool KeptFrame::equalsFramebuffer(Buffer buffer, const std::vector<unsigned char>& bytes) {
  bool equal = bytes.size() == packedSize(width(), height(), transfer(buffer).bytes);
  // A difference stops the reading.
  const std::size_t used = rowBytes(buffer);
  if (equal)
    forEachBand(buffer, bytes, [&](int, const unsigned char* read, const unsigned char* other) {
      equal = std::memcmp(read, other, used) == 0;
      return equal;
    });
  return equal;
}

template <typename RowVisitor>
void KeptFrame::forEachBand(Buffer buffer, const std::vector<unsigned char>& bytes,
                            RowVisitor&& visit) {
  const std::size_t row = packedSize(width(), 1, transfer(buffer).bytes);
  if (row == 0) return;
  // Band by band through a buffer the cache holds: the framebuffer is read once and only the
  // copy compared with comes from memory.
  const int band = int(std::max<std::size_t>(1, kBandBytes / row));
  band_.resize(row * std::size_t(band));
  for (int first = 0; first < height(); first += band) {
    const int rows = std::min(band, height() - first);
    readRows(buffer, first, rows, band_.data());
    for (int r = 0; r < rows; ++r)
      if (!visit(first + r, band_.data() + row * std::size_t(r),
                 bytes.data() + row * std::size_t(first + r)))
        return;
  }
}

std::size_t KeptFrame::rowBytes(Buffer buffer) const {
  // The pixels alone: glReadPixels leaves a row's padding as it was.
  return std::size_t(width()) * std::size_t(transfer(buffer).bytes);
}

int KeptFrame::width() const {
  return region_[2] - region_[0];
}

int KeptFrame::height() const {
  return region_[3] - region_[1];
}

void KeptFrame::findChanged() {
  const int width = this->width();
  changed_ = {width, height(), 0, 0};
  for (const Buffer buffer : {Buffer::Colour, Buffer::Depth}) {
    const std::size_t pixel = std::size_t(transfer(buffer).bytes);
    const std::size_t used = rowBytes(buffer);
    forEachBand(buffer, buffer == Buffer::Colour ? now_.colour : now_.depth,
                [&](int y, const unsigned char* after, const unsigned char* before) {
                  if (std::memcmp(after, before, used) == 0) return true;
                  int first = 0, last = width - 1;
                  while (std::memcmp(after + pixel * std::size_t(first),
                                     before + pixel * std::size_t(first), pixel) == 0)
                    ++first;
                  while (std::memcmp(after + pixel * std::size_t(last),
                                     before + pixel * std::size_t(last), pixel) == 0)
                    --last;
                  changed_ = {std::min(changed_[0], first), std::min(changed_[1], y),
                              std::max(changed_[2], last + 1), std::max(changed_[3], y + 1)};
                  return true;
                });
  }
  // From the region's corner to the viewport's.
  changed_ = {changed_[0] + region_[0], changed_[1] + region_[1], changed_[2] + region_[0],
              changed_[3] + region_[1]};
}

void KeptFrame::readAll() {
  if (!colourRead_) read(Buffer::Colour);
  // Unread, the depth is the one traced at.
  if (!depthRead_) {
    now_.depth = tracedDepth_;
    depthRead_ = true;
  }
}

bool KeptFrame::depthAsTraced() const {
  return readable_ && depthAsTraced_;
}

void KeptFrame::markTraced(const std::array<int, 4>& region) {
  const bool inside = readable_ && region[0] >= region_[0] && region[1] >= region_[1] &&
                      region[2] <= region_[2] && region[3] <= region_[3] &&
                      region[0] <= region[2] && region[1] <= region[3];
  if (inside) {
    // Unread, the depth is the one traced at before, over the same region.
    const std::vector<unsigned char>& read = depthRead_ ? now_.depth : tracedDepth_;
    const std::size_t pixel = std::size_t(transfer(Buffer::Depth).bytes);
    const std::size_t from = packedSize(width(), 1, int(pixel));
    const std::size_t to = packedSize(region[2] - region[0], 1, int(pixel));
    std::vector<unsigned char> cropped(to * std::size_t(region[3] - region[1]), 0);
    for (int y = region[1]; y < region[3]; ++y)
      std::memcpy(cropped.data() + to * std::size_t(y - region[1]),
                  read.data() + from * std::size_t(y - region_[1]) +
                      pixel * std::size_t(region[0] - region_[0]),
                  pixel * std::size_t(region[2] - region[0]));
    tracedDepth_.swap(cropped);
    tracedRegion_ = region;
    tracedLayout_ = layout_;
  } else {
    tracedDepth_.clear();
    tracedRegion_ = {};
  }
  depthAsTraced_ = inside && region == region_;
  forget();
}

void KeptFrame::forget() {
  valid_ = false;
}

bool KeptFrame::restore() {
  if (!readable_) return false;
  if (valid_ && layout_ == keptLayout_ && region_ == keptRegion_) {
    // Two depths equal to the one traced at are equal without a second comparison.
    const std::vector<unsigned char>& depth = depthRead_ ? now_.depth : tracedDepth_;
    const bool sameDepth = (depthAsTraced_ && keptAtTracedDepth_) || depth == keptBefore_.depth;
    if (sameDepth && equalsFramebuffer(Buffer::Colour, keptBefore_.colour)) {
      GlStateScope scope(GlStateScope::kFramebuffers);
      blit(framebuffer_.get(), GLuint(scope.drawFramebuffer()), false);
      return true;
    }
  }
  // The caller composites and keep() keeps the frame with what it was composed over.
  readAll();
  return false;
}

void KeptFrame::keep() {
  valid_ = false;
  if (!readable_ || !colourRead_ || !depthRead_) return;
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
  findChanged();
  GlStateScope scope(GlStateScope::kFramebuffers);
  blit(GLuint(scope.drawFramebuffer()), framebuffer_.get(), true);
  std::swap(keptBefore_, now_);
  colourRead_ = depthRead_ = false;
  keptAtTracedDepth_ = depthAsTraced_;
  keptRegion_ = region_;
  valid_ = true;
}

void KeptFrame::giveUp() {
  colour_ = GlRenderbuffer();
  depth_ = GlRenderbuffer();
  failedLayout_ = layout_;
}

void KeptFrame::blit(unsigned int from, unsigned int to, bool toKept) const {
  // Only what the picture changed: elsewhere the framebuffer is what the kept frame was
  // composed over, which restore() found equal to it.
  if (changed_[0] >= changed_[2] || changed_[1] >= changed_[3]) return;
  // A blit is clipped by the scissor test an application may have left on.
  GlStateScope tests(GlStateScope::kFragmentTests);
  tests.disableFragmentTests();
  const std::array<int, 4>& v = layout_.viewport;
  const std::array<int, 4> drawn{v[0] + changed_[0], v[1] + changed_[1], v[0] + changed_[2],
                                 v[1] + changed_[3]};
  const std::array<int, 4>& kept = changed_;
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
