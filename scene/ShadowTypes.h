#pragma once

#include <cstddef>
#include <vector>

namespace ivshadow {

// Types that the GL passes (callbacks/) and the CPU tracers (raytrace/) both speak. They live
// here, with no GL and no Embree, so that neither of those layers has to include the other.

// How a surface filters light in a deep shadow map; the values are deep_shadow_common.glsl's
// kColour* constants.
enum class ShadowColourModel : int { Monochrome = 0, Saturate = 1, Power = 2 };

// One captured layer of visible surfaces, read back from the GL capture pass: per pixel
// (rows bottom-up, as GL stores them) the position in the group's coordinates and window
// depth (depth 1: nothing), and the geometric normal with a flag (w == 2: shaded by the group
// and to be traced).
struct SurfaceLayer {
  int width = 0;
  int height = 0;
  std::vector<float> position;  // x, y, z, window depth
  std::vector<float> normal;    // x, y, z, flag

  bool traced(std::size_t pixel) const {
    return position[pixel * 4 + 3] < 1.0f && normal[pixel * 4 + 3] > 1.5f;
  }
};

}  // namespace ivshadow
