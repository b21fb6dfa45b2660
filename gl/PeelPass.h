#pragma once

#include "gl/GlHandles.h"
#include "gl/GlPassTimer.h"
#include "gl/GlProgram.h"

#include <array>
#include <memory>
#include <string>

namespace ivshadow {

class FragmentListPass;
class GlStateScope;
struct ShadingLocations;

// The GL side of depth peeling (SoPeelingSeparator, a peeling SoTransparentShadowGroup) in
// one context: the peel targets (depth range, front accumulation, back layer, back
// accumulation, each sized to the viewport), the copy of the opaque depth, the compositing
// program and the progress flag. A frame is
//   beginOpaque(); <Coin draws the children>; endOpaque();
//   begin(); [startPass(i); <Coin draws the children>; finishPass(i)]...; end();
// with the opaque variant of the shading program bound for the first traversal, a peel
// variant for the others, and the peel variants' units set through setPeelUniforms() per
// pass.
class PeelPass {
 public:
  static std::unique_ptr<PeelPass> create(std::string& whyNot);
  ~PeelPass();

  // GL_MAX_TEXTURE_IMAGE_UNITS of the context (read once).
  int textureUnits() const { return textureUnits_; }

  // Allocates the targets for a viewport (x, y, width, height) in window coordinates, before
  // anything is drawn. Empty when they are ready; else what GL said (GL_OUT_OF_MEMORY, an
  // incomplete framebuffer), and the subgraph cannot be peeled in this viewport.
  std::string prepare(int x, int y, int width, int height);

  // Around the opaque pass: binds the progress flag, cleared, for the opaque variant to raise
  // on a transparent fragment it discards. endOpaque() restores the binding and returns
  // whether one was raised (waiting for the pass); without one there is nothing to peel.
  void beginOpaque();
  bool endOpaque();

  // Saves GL state, sizes the targets to cover the viewport (x, y, width, height) in window
  // coordinates, copies the depth of the opaque pass from the current framebuffer and
  // switches to the peel targets with MAX blending.
  void begin(int x, int y, int width, int height);
  // Clears this pass's targets and binds the previous pass's as textures.
  void startPass(int pass);
  // Blends a dual pass's back layer into the back accumulation; returns whether some
  // fragment lay strictly inside the range still to peel (another pass has work).
  bool finishPass(int pass, bool dual);
  // Composites front and back layers over the opaque picture in the framebuffer that was
  // current at begin() (nothing when `passes` is 0), and restores the saved state.
  void end(int passes);

  // GPU time from begin() to the end of end(), waiting for it.
  double gpuMs() const { return timer_.elapsedMs(); }

  // Sets the texture units of a peel variant of the shading program (peel.frag).
  void setPeelUniforms(const ShadingLocations& program) const;

  // This context's fragment lists, made at the first call; null when they cannot be made
  // (`whyNot` says why, at that first call only).
  FragmentListPass* fragmentLists(std::string& whyNot);

 private:
  PeelPass() = default;
  std::string allocate(int width, int height);

  GlProgram composite_;
  GlBuffer progress_;
  GlVertexArray emptyVertexArray_;
  int width_ = 0;
  int height_ = 0;
  std::array<GlTexture, 2> depthRange_;
  std::array<GlTexture, 2> front_;
  GlTexture backLayer_;
  GlTexture backAccumulation_;
  GlTexture opaqueDepth_;
  std::array<GlFramebuffer, 2> peelFramebuffer_;
  GlFramebuffer backFramebuffer_;
  std::unique_ptr<GlStateScope> saved_;
  std::unique_ptr<GlStateScope> savedOpaque_;
  // The debugger's groups of the opaque pass, of the peeling (begin() to end()) and of the
  // current peel pass (startPass() to finishPass()).
  std::unique_ptr<GlDebugGroup> opaqueGroup_;
  std::unique_ptr<GlDebugGroup> peelingGroup_;
  std::unique_ptr<GlDebugGroup> passGroup_;
  int targetFramebuffer_ = 0;
  std::array<int, 4> viewport_{};
  int textureUnits_ = 0;
  int firstUnit_ = 0;
  GlPassTimer timer_;
  std::unique_ptr<FragmentListPass> lists_;
  bool listsTried_ = false;
};

}  // namespace ivshadow
