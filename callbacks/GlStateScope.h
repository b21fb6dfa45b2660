#pragma once

#include <array>
#include <vector>

namespace ivshadow {

// Saves the GL state that the plugin's own passes change in the middle of Coin's traversal
// and puts it back on destruction, so Coin's lazy state cache stays true: framebuffer and
// viewport, program and vertex array, depth, clip control, the per-fragment switches Coin
// may have left on (blending, alpha test, stipple, clip planes, ...), and the textures bound
// to the units the pass uses.
class GlStateScope {
 public:
  enum class Extent {
    TextureUnits,  // only the bindings of the given units and the active unit
    WholePass      // everything listed above
  };
  // `textureUnits`: the units whose bindings (2D and 2D-array) the pass will change.
  GlStateScope(Extent extent, const std::vector<int>& textureUnits);
  ~GlStateScope();
  GlStateScope(const GlStateScope&) = delete;
  GlStateScope& operator=(const GlStateScope&) = delete;

  // Switches off every per-fragment and clipping test the saved state may have on, and
  // fills polygons (Coin may have drawn lines or points for a DrawStyle).
  void disableFragmentTests() const;

 private:
  struct UnitBinding {
    int unit;
    int texture2D;
    int texture2DArray;
    int sampler;
  };
  Extent extent_;
  int drawFramebuffer_ = 0;
  int readFramebuffer_ = 0;
  std::array<int, 4> viewport_{};
  int program_ = 0;
  int vertexArray_ = 0;
  int arrayBuffer_ = 0;
  int storageBuffer_ = 0;
  std::array<int, 2> storageBufferBindings_{};
  int activeTexture_ = 0;
  int depthFunc_ = 0;
  unsigned char depthMask_ = 1;
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
