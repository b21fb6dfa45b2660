#pragma once

#include "gl/GlHandles.h"
#include "ivshadow/Export.h"

#include <array>
#include <optional>
#include <vector>

namespace ivshadow {

// A traced group's frame, kept for the frames that change nothing, in one context. Each frame
// reads what GL drew before the picture as it is stored (colour and depth, unconverted: a plain
// copy) and compares it with what the kept frame was composed over; while they are equal the
// framebuffer the picture left is put back by one blit instead of compositing the picture
// again. On llvmpipe the composite runs a fragment program over every pixel of the viewport,
// which costs more than plain Coin's whole frame of a small scene; the read, the comparison and
// the blit are copies. The same read tells whether the depth is still the one the picture was
// traced at, without converting it to floats.
// Only a single-sampled framebuffer drawing into the one buffer it reads, with every colour
// channel writable, is kept; for any other readBefore() says no and the caller composites.
class IVSHADOW_INTERNAL KeptFrame {
 public:
  // Reads the draw framebuffer over `viewport` (x, y, width, height) as stored: what GL drew
  // before the picture this frame. False when this framebuffer cannot be kept.
  bool readBefore(const std::array<int, 4>& viewport);
  // Whether the depth readBefore() read is the one the picture was traced at (markTraced()).
  bool depthAsTraced() const;
  // The picture was traced at the depth readBefore() read this frame.
  void markTraced();
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

  // Lets go of a copy GL could not hold, and remembers its layout.
  void giveUp();
  // Blits the viewport between the draw framebuffer and the copy, colour, depth and stencil.
  void blit(unsigned int from, unsigned int to, bool toKept) const;

  bool readable_ = false;  // this frame's readBefore() read
  Layout layout_;          // this frame's
  Stored now_;             // read this frame
  std::vector<unsigned char> tracedDepth_;
  bool depthAsTraced_ = false;  // now_.depth == tracedDepth_
  bool valid_ = false;          // a frame is kept
  Layout keptLayout_;
  Stored keptBefore_;               // what the kept frame was composed over
  bool keptAtTracedDepth_ = false;  // keptBefore_.depth == tracedDepth_
  GlFramebuffer framebuffer_;
  GlRenderbuffer colour_;
  GlRenderbuffer depth_;
  std::optional<Layout> failedLayout_;
};

}  // namespace ivshadow
