#pragma once

#include "ivshadow/Export.h"

#include <glm/vec4.hpp>

class SbColor;

namespace ivshadow {

// The diffuse colour and opacity GL draws a surface with: Coin packs them into 8 bits a
// channel before it sends them (SbColor::getPackedValue, SoLazyElement), without clamping, so
// that 1.7 is drawn as 0.7 (what users see in every Coin viewer). The tracer and the reference
// take the same 8-bit values, and a value outside 0..1 is reported once.
IVSHADOW_INTERNAL glm::vec4 drawnColour(const SbColor& diffuse, float transparency);

}  // namespace ivshadow
