#pragma once

#include "gl/ShaderConstants.h"
#include "ivshadow/Export.h"

#include <array>
#include <utility>
#include <vector>

namespace ivshadow {

// Saves the GL state that one of the plugin's passes changes in the middle of Coin's
// traversal and puts it back on destruction, so Coin's lazy state cache stays true. Each
// query is a round trip into the driver, so the scope reads only the groups the pass names
// in `changes`, and only the texture targets it binds on the units it names.
class IVSHADOW_INTERNAL GlStateScope {
 public:
  // The groups of state a pass may change (combined with |).
  enum Change : unsigned {
    kFramebuffers = 1u << 0,  // draw and read framebuffer bindings
    kViewport = 1u << 1,
    kProgram = 1u << 2,  // the program in use
    kVertexArray = 1u << 3,
    // generic and indexed (0 .. kStorageBindings - 1) shader storage bindings
    kStorageBuffers = 1u << 4,
    kBlendFunction = 1u << 5,  // blend functions and equations
    kDepth = 1u << 6,          // depth function, write mask and range
    kColourMask = 1u << 7,
    kClipControl = 1u << 8,
    // Blending, depth test, culling and every other per-fragment or clipping switch Coin may
    // have left on, and the polygon mode: what disableFragmentTests() changes.
    kFragmentTests = 1u << 9,
    kImageBindings = 1u << 10,  // image units 0 .. kImageUnits - 1 (ShaderConstants.h)
  };
  struct Textures {
    std::vector<int> units;             // units the pass binds textures on
    std::vector<unsigned int> targets;  // the targets it binds there (GL_TEXTURE_2D, ...)
  };

  explicit GlStateScope(unsigned int changes, const Textures& textures = {});
  // The queries a scope for `changes` and `textures` makes in the current context: one a
  // value of glGetIntegerv, glGetIntegeri_v, glGetBooleanv or glIsEnabled (the depth range,
  // read with glGetDoublev, is not counted). Tests hold a steady frame to it.
  static int queriesFor(unsigned int changes, const Textures& textures = {});
  ~GlStateScope();
  GlStateScope(const GlStateScope&) = delete;
  GlStateScope& operator=(const GlStateScope&) = delete;

  // Switches off every per-fragment and clipping test the saved state may have on, and
  // fills polygons (Coin may have drawn lines or points for a DrawStyle). Needs
  // kFragmentTests.
  void disableFragmentTests() const;
  // The draw framebuffer found (kFramebuffers): where the pass's result goes.
  int drawFramebuffer() const { return drawFramebuffer_; }

 private:
  struct UnitBinding {
    int unit;
    unsigned int target;
    int texture;
  };
  unsigned int changes_;
  int drawFramebuffer_ = 0;
  int readFramebuffer_ = 0;
  std::array<int, 4> viewport_{};
  int program_ = 0;
  int vertexArray_ = 0;
  int storageBuffer_ = 0;
  std::array<int, kStorageBindings> storageBufferBindings_{};
  struct ImageBinding {
    int texture, level, layered, layer, access, format;
  };
  std::array<ImageBinding, kImageUnits> images_{};
  int activeTexture_ = 0;
  int depthFunc_ = 0;
  unsigned char depthMask_ = 1;
  std::array<double, 2> depthRange_{0.0, 1.0};
  std::array<unsigned char, 4> colourMask_{};
  std::array<int, 4> blendFunc_{};
  std::array<int, 2> blendEquation_{};
  std::array<int, 2> polygonMode_{};
  int clipOrigin_ = 0;
  int clipDepthMode_ = 0;
  std::vector<std::pair<unsigned int, bool>> enables_;
  std::vector<UnitBinding> units_;
};

}  // namespace ivshadow
