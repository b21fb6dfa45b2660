#pragma once

#include "scene/ShadowTypes.h"

#include <array>
#include <string_view>

namespace ivshadow {

// The per-light data of the camera-pass program (lighting.glsl), one row a field, written
// once: it declares the C++ arrays ShadingUniforms fills (LightSlotArrays), the GLSL uniform
// arrays (ShaderConstants.cpp writes them as IVSHADOW_LIGHT_SLOT_UNIFORMS for lighting.glsl)
// and ShadingUniforms::apply's upload of each, so that a name, a type or a length cannot differ
// between the two languages. Each is an array over the light slots (kMaxGlLights), element
// `slot * perSlot + i` the i-th value of the slot's light. Columns: GLSL type, values of that
// type a slot, C++ element type, member, GLSL name, initial value.
//   mapLight        the light's position in the group's coordinates (a directional light's
//                   direction towards it)
//   mapLightEye     ... and in eye coordinates
//   mapParams       resolution, 1 for a directional light, bias (texels), filter width
//                   (texels; 0: the nearest texel)
//   mapColoured     whether the map keeps colour
//   mapProjection   how the map sees its casters (MapProjection, gl/MapFrame.h)
//   mapLookup       a one-face map's lookup: the group's coordinates to (x w, y w, depth, w),
//                   column-major
//   mapTexelScale   a texel's size at depth d, times the resolution: x d + y
//   mapFaceFirst    array layer of each face's first layer
//   mapFaceLayers   layers stored for each face
//   mapSlices       an opacity map's sliced distances (near, far) and slices per face; 0
//                   slices: a deep shadow map
//   mapRay          index among the traced (RAYS) lights, -1 for a light with a map
#define IVSHADOW_LIGHT_SLOT_FIELDS(X)                  \
  X(vec3, 1, float, mapLight, uMapLight, {})           \
  X(vec3, 1, float, mapLightEye, uMapLightEye, {})     \
  X(vec4, 1, float, mapParams, uMapParams, {})         \
  X(int, 1, int, mapColoured, uMapColoured, {})        \
  X(int, 1, int, mapProjection, uMapProjection, {})    \
  X(mat4, 1, float, mapLookup, uMapLookup, {})         \
  X(vec2, 1, float, mapTexelScale, uMapTexelScale, {}) \
  X(int, 6, int, mapFaceFirst, uMapFaceFirst, {})      \
  X(int, 6, int, mapFaceLayers, uMapFaceLayers, {})    \
  X(vec3, 1, float, mapSlices, uMapSlices, {})         \
  X(int, 1, int, mapRay, uMapRay, LightSlotArrays::noRays())

// Scalars a GLSL type holds.
constexpr int glslComponents(std::string_view type) {
  return type == "mat4" ? 16 : type == "vec4" ? 4 : type == "vec3" ? 3 : type == "vec2" ? 2 : 1;
}

struct LightSlotArrays {
  static constexpr int kSlots = kMaxGlLights;
  static std::array<int, kSlots> noRays() {
    std::array<int, kSlots> none{};
    none.fill(-1);
    return none;
  }
#define IVSHADOW_LIGHT_SLOT_MEMBER(glslType, perSlot, Element, member, uniform, initial) \
  std::array<Element, kSlots * perSlot * glslComponents(#glslType)> member = initial;
  IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_LIGHT_SLOT_MEMBER)
#undef IVSHADOW_LIGHT_SLOT_MEMBER
};

// The GLSL's scalars a slot, from the table; the C++ record holds exactly those, 4 bytes each
// as std430 and glProgramUniform* read them, without padding.
#define IVSHADOW_LIGHT_SLOT_VALUES(glslType, perSlot, Element, member, uniform, initial) \
  +perSlot* glslComponents(#glslType)
inline constexpr int kLightSlotValues = 0 IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_LIGHT_SLOT_VALUES);
#undef IVSHADOW_LIGHT_SLOT_VALUES
static_assert(sizeof(LightSlotArrays) == std::size_t(kMaxGlLights * kLightSlotValues) * 4,
              "the per-light record must hold the GLSL arrays' values and nothing else");

}  // namespace ivshadow
