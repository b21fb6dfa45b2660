#pragma once

#include "gl/LightSlotFields.h"
#include "ivshadow/Export.h"

#include <string_view>
#include <vector>

namespace ivshadow {

class UniformLocations;

// The uniforms the plugin sets on its shading programs (nodes/ShadingProgram.h), by their GLSL
// names: ShadingUniforms' (with LightSlotFields.h's per-light arrays), the peel passes', the
// ray capture's and the texture coordinate functions'.
// clang-format off
#define IVSHADOW_SHADING_UNIFORMS(X) \
  X(textureMap0) \
  X(uLightCount) \
  X(uMapCount) \
  X(uEyeToLocal) \
  X(uFogType) \
  X(uMapDepth) \
  X(uMapVisibility) \
  X(uRayLayers) \
  X(uRayOpaque) \
  X(uRayPrevious) \
  X(uRayDepth) \
  X(uRayVisibility) \
  X(uBounceAtlas) \
  X(uBounceLights) \
  X(uBounceCount) \
  X(uBounceTiles) \
  X(uBounceMapSize) \
  X(uBounceLift) \
  X(uEyeToLocalNormal) \
  X(uPeelDepth) \
  X(uPeelFront) \
  X(uRayFirstTransparent) \
  X(uTexGen)
// clang-format on

// Where a linked shading program has those uniforms, found once when Coin links it in a
// context, so that a frame sets them with no look-up by name. -1 for a uniform the variant
// compiled out (glProgramUniform* ignores it). A misspelt name would be -1 in every variant:
// ShadingProgram says once which names no shading program declares (undeclared).
struct IVSHADOW_INTERNAL ShadingLocations {
  unsigned int program = 0;
#define IVSHADOW_SHADING_LOCATION(name) int name = -1;
  IVSHADOW_SHADING_UNIFORMS(IVSHADOW_SHADING_LOCATION)
#undef IVSHADOW_SHADING_LOCATION
#define IVSHADOW_LIGHT_SLOT_LOCATION(glslType, perSlot, Element, member, uniform, initial) \
  int uniform = -1;
  IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_LIGHT_SLOT_LOCATION)
#undef IVSHADOW_LIGHT_SLOT_LOCATION

  ShadingLocations() = default;
  // The locations in `program`.
  explicit ShadingLocations(const UniformLocations& program);

  // The names above that `declarations` does not mention as a word.
  static std::vector<std::string_view> undeclared(std::string_view declarations);
};

}  // namespace ivshadow
