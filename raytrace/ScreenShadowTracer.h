#pragma once

#include "callbacks/GlLimits.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ivshadow {

class CasterScene;

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

struct RayLight {
  float position[3] = {0.0f, 0.0f, 0.0f};  // in the group's coordinates
  ShadowColourModel model = ShadowColourModel::Monochrome;
};

// Traces one shadow ray per traced pixel, layer (the first `layerCount` of `layers`) and light
// through `casters` on every core. Writes RGBA visibility as 16-bit floats (alpha 1; 1 where
// nothing was traced) per light, then layer, then pixel into `visibility` — the layout and
// format of the shading program's uRayVisibility array, so the upload is a copy — reusing its
// memory from frame to frame. Returns the number of rays traced.
std::size_t traceScreenShadows(const CasterScene& casters, const std::vector<SurfaceLayer>& layers,
                               std::size_t layerCount, const std::vector<RayLight>& lights,
                               std::vector<std::uint16_t>& visibility);

}  // namespace ivshadow
