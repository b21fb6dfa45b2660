#pragma once

#include "gl/FramebufferFormats.h"
#include "gl/GlHandles.h"
#include "ivshadow/Export.h"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace ivshadow {

// A traced group's frame, kept for the frames that change nothing, in one context. Each frame
// reads what GL drew before the picture as it is stored (colour and depth, unconverted: a plain
// copy) and compares it with what the kept frame was composed over; while they are equal the
// framebuffer the picture left is put back by one blit (of the box where the picture changed
// what GL drew) instead of compositing the picture again. On llvmpipe the composite runs a fragment
// program over every pixel of the viewport, which costs more than plain Coin's whole frame of a
// small scene; the read, the comparison and the blit are copies. The reads go band by band through
// a buffer the cache holds, compared as they come: only a frame that differs is read whole into
// memory, to be kept. The same reads tell whether the depth is still the one the picture was traced
// at, without converting it to floats. Only the region the picture may change is read (the box
// around the traced triangles as its camera sees them): elsewhere the picture leaves whatever GL
// drew. Only a single-sampled framebuffer drawing into the one
// buffer it reads, with every colour channel writable, is kept; for any other readBefore() says no
// and the caller composites.
class IVSHADOW_INTERNAL KeptFrame {
 public:
  // Reads the draw framebuffer over `region` of `viewport` (x, y, width, height) as stored:
  // what GL drew before the picture this frame (its depth now; its colour when restore()
  // compares it, so nothing may draw in between). `region` ({x0, y0, x1, y1} from the
  // viewport's corner, x1 and y1 past the end) holds every pixel the picture may change: the
  // one markTraced() was given while the picture is the same, else the whole viewport. False
  // when this framebuffer cannot be kept.
  bool readBefore(const std::array<int, 4>& viewport, const std::array<int, 4>& region);
  // Whether the depth readBefore() read is the one the picture was traced at (markTraced()).
  bool depthAsTraced() const;
  // The picture was traced at the depth readBefore() read this frame, and changes pixels in
  // `region` alone (within readBefore()'s).
  void markTraced(const std::array<int, 4>& region);
  // Puts back the frame kept when what this frame's readBefore() read equals what it was
  // composed over, over the same viewport; false (nothing drawn) otherwise.
  bool restore();
  // Keeps the framebuffer over the viewport as the picture left it: composed over what this
  // frame's readBefore() read. Keeps nothing when GL cannot hold the copy.
  void keep();
  // The picture changed: the frame kept is no longer its.
  void forget();

 private:
  struct Stored {
    std::vector<unsigned char> colour;
    std::vector<unsigned char> depth;
  };
  // What the draw framebuffer is, as the copies need it to be the same.
  struct Layout {
    std::array<int, 4> viewport{};
    unsigned int colourFormat = 0;
    unsigned int depthFormat = 0;
    bool operator==(const Layout& other) const {
      return viewport == other.viewport && colourFormat == other.colourFormat &&
             depthFormat == other.depthFormat;
    }
  };

  enum class Buffer { Colour, Depth };
  // The rows read at once when comparing: well inside a core's L2 cache.
  static constexpr std::size_t kBandBytes = 256 * 1024;

  PixelTransfer transfer(Buffer buffer) const;
  // Reads `rows` rows of the viewport from its row `first` on, packed, into `into`.
  void readRows(Buffer buffer, int first, int rows, unsigned char* into) const;
  // Reads the whole viewport of `buffer` into now_.
  void read(Buffer buffer);
  // Whether the framebuffer's `buffer` over the viewport is `bytes`, as read().
  bool equalsFramebuffer(Buffer buffer, const std::vector<unsigned char>& bytes);
  // Calls visit(y, read, bytes' row y) for each row y of the viewport read from the
  // framebuffer's `buffer`, until it returns false.
  template <typename RowVisitor>
  void forEachBand(Buffer buffer, const std::vector<unsigned char>& bytes, RowVisitor&& visit);
  std::size_t rowBytes(Buffer buffer) const;
  // The region's size.
  int width() const;
  int height() const;
  // Sets changed_ to the box where the framebuffer differs from now_.
  void findChanged();
  // Completes now_: the colour read, the depth read or known to be the one traced at.
  void readAll();
  // Lets go of a copy GL could not hold, and remembers its layout.
  void giveUp();
  // Blits changed_ between the draw framebuffer and the copy, colour, depth and stencil.
  void blit(unsigned int from, unsigned int to, bool toKept) const;

  bool readable_ = false;        // this frame's readBefore() read
  Layout layout_;                // this frame's
  std::array<int, 4> region_{};  // this frame's, in the viewport
  Stored now_;                   // read this frame, where colourRead_ and depthRead_ say
  bool colourRead_ = false;
  bool depthRead_ = false;  // else the depth is tracedDepth_ when depthAsTraced_
  std::vector<unsigned char> band_;
  std::vector<unsigned char> tracedDepth_;  // over tracedRegion_
  std::array<int, 4> tracedRegion_{};
  Layout tracedLayout_;         // the viewport and formats tracedDepth_ was read in
  bool depthAsTraced_ = false;  // now_.depth == tracedDepth_
  bool valid_ = false;          // a frame is kept
  Layout keptLayout_;
  Stored keptBefore_;  // what the kept frame was composed over, over keptRegion_
  std::array<int, 4> keptRegion_{};
  // Where the kept frame differs from keptBefore_: x0, y0, x1, y1 in the viewport, x1 and y1
  // past the end; empty when x0 >= x1. The blits copy it alone.
  std::array<int, 4> changed_{};
  bool keptAtTracedDepth_ = false;  // keptBefore_.depth == tracedDepth_
  GlFramebuffer framebuffer_;
  GlRenderbuffer colour_;
  GlRenderbuffer depth_;
  std::optional<Layout> failedLayout_;
};

}  // namespace ivshadow
