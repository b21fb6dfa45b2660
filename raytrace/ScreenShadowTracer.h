#pragma once

#include "scene/ShadowTypes.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ivshadow {

class CasterScene;

struct RayLight {
  // In the group's coordinates; for a directional light the unit direction towards it.
  float position[3] = {0.0f, 0.0f, 0.0f};
  bool directional = false;
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
