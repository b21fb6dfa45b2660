#pragma once

#include "gl/GlHandles.h"
#include "gl/GlProgram.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace ivshadow {

class GlStateScope;

// The GL side of order-independent transparency by per-pixel fragment lists in one context
// (SoPeelingSeparator's FRAGMENT_LISTS, a peeling SoTransparentShadowGroup): the list buffer
// (ShaderConstants.h: kFragmentBytes a fragment; kFixedFragmentsPerPixel slots of its own a
// pixel, then an overflow list), each pixel's head and count images, a copy
// of the opaque pass's depth in a framebuffer with no colour, and the resolve program. After
// the opaque pass a frame is
//   begin(); <Coin draws the children, the list variant bound>; finish();
// and, when finish() says Stored, resolve(); when it says Grow, the same again once (the
// buffer now holds what the view needs); otherwise the view is peeled instead.
class FragmentListPass {
 public:
  // Null, with the reason, when the context lacks what the lists need.
  static std::unique_ptr<FragmentListPass> create(std::string& whyNot);
  ~FragmentListPass();

  enum class Outcome {
    Stored,    // every fragment is in its list
    Grow,      // the buffer was too small; it has been enlarged for another begin()
    Crowded,   // some pixel holds more than kMaxFragmentsPerPixel fragments
    TooLarge,  // the view needs more storage than GL gives
  };

  // Saves GL state, sizes the images to cover the viewport (x, y, width, height) in window
  // coordinates, copies the opaque depth from the current framebuffer, empties the lists and
  // switches to the list framebuffer with the buffer and images bound. False, with nothing
  // changed, when GL cannot give the images or a first buffer (tooLargeReason() says why).
  bool begin(int x, int y, int width, int height);
  // After a begin() that returned true: waits for the list pass, restores the state begin()
  // saved and says what it stored.
  Outcome finish();
  // Composites each pixel's sorted list over the framebuffer current at begin().
  void resolve();
  // Fragments the last pass stored, after finish() said Stored.
  std::uint64_t fragments() const { return stored_; }
  // The fragments a pixel keeps in slots of its own (kFixedFragmentsPerPixel, or fewer where
  // GL could not give the storage), after a begin().
  int slots() const { return fixedLayers_; }
  // Why the view cannot be listed, after begin() returned false or finish() TooLarge.
  std::string tooLargeReason() const;

 private:
  FragmentListPass() = default;
  // Empty, or what GL could not give (GlAllocationCheck).
  std::string allocateImages(int width, int height);
  // The slots of fixedLayers_ fragments a pixel and room for `overflow` more.
  bool allocateList(std::uint64_t overflow);
  std::uint64_t bytesFor(std::uint64_t overflow) const;
  void countStored();

  GlProgram resolve_;
  GlVertexArray emptyVertexArray_;
  GlBuffer list_;
  int fixedLayers_ = 0;                 // slots of its own per pixel (kFixedFragmentsPerPixel)
  std::uint64_t overflowCapacity_ = 0;  // overflow fragments the list buffer holds
  std::uint64_t maxBytes_ = 0;          // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  std::uint64_t overflowUsed_ = 0;      // overflow fragments the last pass tried to store
  std::uint64_t stored_ = 0;
  std::string failure_;  // what begin() could not allocate
  int width_ = 0;
  int height_ = 0;
  GlTexture heads_;
  GlTexture counts_;
  GlTexture opaqueDepth_;
  GlFramebuffer framebuffer_;
  std::unique_ptr<GlStateScope> saved_;
  std::unique_ptr<GlDebugGroup> passGroup_;  // the debugger's group, begin() to finish()
  int targetFramebuffer_ = 0;
  std::array<int, 4> viewport_{};
};

}  // namespace ivshadow
