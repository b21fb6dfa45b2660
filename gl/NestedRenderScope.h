#pragma once

#include <array>

namespace ivshadow {

// Everything a second Coin render action, applied in the middle of the outer action's
// traversal, may leave changed in GL, saved for the scope's lifetime and put back: the whole
// attribute and client attribute stacks (enables, lights, material, depth, blending,
// viewport, texture bindings of every unit), the projection, model-view and texture
// matrices (the first texture unit's, where Coin's texture transforms go), the program, vertex
// array, array buffer, framebuffers and active texture unit. Other buffer bindings (pixel
// pack and unpack, uniform buffers) are not saved: Coin's fixed-function drawing leaves them.
// Without it the outer action's elements would believe GL holds what they last sent while
// it held the nested action's last state.
class NestedRenderScope {
 public:
  NestedRenderScope();
  ~NestedRenderScope();
  NestedRenderScope(const NestedRenderScope&) = delete;
  NestedRenderScope& operator=(const NestedRenderScope&) = delete;

 private:
  int program_ = 0;
  int vertexArray_ = 0;
  int arrayBuffer_ = 0;
  int drawFramebuffer_ = 0;
  int readFramebuffer_ = 0;
  int activeTexture_ = 0;
  int matrixMode_ = 0;
  std::array<float, 16> projection_{};
  std::array<float, 16> modelView_{};
  std::array<float, 16> texture_{};
};

}  // namespace ivshadow
