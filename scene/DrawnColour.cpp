#include "scene/DrawnColour.h"

#include "scene/WarnOnce.h"

#include <Inventor/SbColor.h>
#include <Inventor/errors/SoDebugError.h>

#include <cstdint>

namespace ivshadow {

glm::vec4 drawnColour(const SbColor& diffuse, float transparency) {
  bool isOutside = false;
  float outside = 0.0f;
  for (int i = 0; i < 3; ++i)
    if (!(diffuse[i] >= 0.0f && diffuse[i] <= 1.0f)) {
      isOutside = true;
      outside = diffuse[i];
    }
  if (isOutside && firstWarning(nullptr, "diffuse colour outside 0..1"))
    SoDebugError::postWarning("ivshadow",
                              "a diffuse colour of %g: Coin packs colours into 8 bits without "
                              "clamping them, and every path draws what Coin draws (1.7 as 0.7)",
                              double(outside));
  // Coin's own packing, as it runs before GL sees the colour.
  const std::uint32_t packed = diffuse.getPackedValue(transparency);
  return glm::vec4(float((packed >> 24) & 0xffu), float((packed >> 16) & 0xffu),
                   float((packed >> 8) & 0xffu), float(packed & 0xffu)) /
         255.0f;
}

}  // namespace ivshadow
