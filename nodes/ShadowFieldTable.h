#pragma once

#include "gl/ShaderConstants.h"
#include "ivshadow/ShadowFieldList.h"
#include "ivshadow/ShadowMethod.h"
#include "ivshadow/SoDeepShadowLight.h"

#include <cstddef>
#include <iterator>

namespace ivshadow {

// An opacity map's slices per face (the slices field's default): the four of seeds/002's
// implementation, one draw per face (kOpacitySlicesPerDraw).
inline constexpr int kDefaultOpacitySlices = 4;
// The map's depth offset towards the light, in texels at the receiver, beyond the receiver's
// own plane (lighting.glsl). The lookup compares the stored surfaces with that plane, so the
// offset covers only float rounding; a tenth of a texel was the most accurate on the bundled
// scenes (docs/TRADEOFF.md, "Bias"), and light can leak only where a caster lies that close.
inline constexpr float kDefaultMapBias = 0.1f;
// Bilinear PCF: the visibility of the four texels around the point, weighted by their
// overlap with one texel's square. It was 0.7 to 1.3 dB nearer the exact picture than the
// nearest texel on every bundled scene of the trade, and a 3 x 3 square farther
// (docs/TRADEOFF.md, "Defaults").
inline constexpr SoDeepShadowLight::Filter kDefaultMapFilter = SoDeepShadowLight::PCF;
inline constexpr int kDefaultMapFilterSize = 1;
// The widest PCF square, in texels: the mean over 81 texels per lookup.
inline constexpr int kMaxMapFilterSize = 9;

// The shadow fields of ivshadow/ShadowFieldList.h, in its order: a field's row in
// kShadowFields.
enum class ShadowFieldId {
#define IVSHADOW_FIELD_ID(type, name) name,
  IVSHADOW_SHADOW_FIELDS(IVSHADOW_FIELD_ID) IVSHADOW_MAP_RANGE_FIELDS(IVSHADOW_FIELD_ID)
#undef IVSHADOW_FIELD_ID
};

enum class ShadowFieldKind { Enum, Int, Float };

// What one end of a field's range means.
enum class Bound {
  Panel,           // only the viewer's spin box stops there; the nodes take any value
  Clamp,           // the nodes clamp to it, saying so once per node and field
  MaxTextureSize,  // the nodes clamp to GL's largest texture; the viewer stops at the value
};

struct FieldBound {
  double value = 0.0;
  Bound kind = Bound::Panel;
};

// The names an enum field reads and writes, indexed by value (SoDeepShadowLight's enums).
struct EnumNames {
  const char* type = nullptr;  // the enum's name in the nodes' field data ("ShadowColor")
  const char* const* names = nullptr;
  std::size_t count = 0;
};

// The bits of the methods that read a field (methodBit); a field that none of a frame's methods
// read does nothing there (IdleFields).
constexpr unsigned methodBit(ShadowMethod method) {
  return 1u << unsigned(method);
}
inline constexpr unsigned kMapMethods =
    methodBit(ShadowMethod::Map) | methodBit(ShadowMethod::OpacityMap);
inline constexpr unsigned kEveryMethod =
    methodBit(ShadowMethod::Rays) | methodBit(ShadowMethod::Volumes) | kMapMethods;

// One shadow field: what a fresh node holds, what the nodes accept, what the viewer offers.
struct ShadowFieldSpec {
  const char* name;
  ShadowFieldKind kind;
  EnumNames enumNames;  // for an enum field
  double defaultValue;
  FieldBound low;  // numbers: the range (the viewer's spin box, and where it clamps, the nodes')
  FieldBound high;
  double step;      // the viewer's spin box
  int decimals;     // ...
  unsigned readBy;  // the methods whose shadows read it
};

inline constexpr const char* kShadowColorNames[] = {"AUTO", "MONOCHROME", "COLORED"};
inline constexpr const char* kColorModelNames[] = {"SATURATE", "POWER"};
inline constexpr const char* kPrecisionNames[] = {"FLOAT", "HALF"};
inline constexpr const char* kFilterNames[] = {"NONE", "PCF"};
inline constexpr const char* kLayerOverflowNames[] = {"MERGE", "TRUNCATE"};

template <std::size_t N>
constexpr EnumNames enumNames(const char* type, const char* const (&names)[N]) {
  return {type, names, N};
}

// The values of SoDeepShadowLight's enums are the indices of the names above.
static_assert(SoDeepShadowLight::AUTO == 0 && SoDeepShadowLight::MONOCHROME == 1 &&
              SoDeepShadowLight::COLORED == 2);
static_assert(SoDeepShadowLight::SATURATE == 0 && SoDeepShadowLight::POWER == 1);
static_assert(SoDeepShadowLight::FLOAT == 0 && SoDeepShadowLight::HALF == 1);
static_assert(SoDeepShadowLight::NONE == 0 && SoDeepShadowLight::PCF == 1);
static_assert(SoDeepShadowLight::MERGE == 0 && SoDeepShadowLight::TRUNCATE == 1);
// ... and the method's are ShadowMethod's, whose one name table the field reads (files say
// AUTO; the C++ name is AUTO_METHOD, since ShadowColor has AUTO).
static_assert(int(ShadowMethod::Auto) == SoDeepShadowLight::AUTO_METHOD &&
              int(ShadowMethod::Map) == SoDeepShadowLight::MAP &&
              int(ShadowMethod::Rays) == SoDeepShadowLight::RAYS &&
              int(ShadowMethod::Volumes) == SoDeepShadowLight::VOLUMES &&
              int(ShadowMethod::OpacityMap) == SoDeepShadowLight::OPACITY_MAP &&
              kShadowMethodCount == SoDeepShadowLight::OPACITY_MAP + 1);

constexpr ShadowFieldSpec enumField(const char* name, EnumNames names, int defaultValue,
                                    unsigned readBy) {
  return {name, ShadowFieldKind::Enum, names, double(defaultValue), {}, {}, 0.0, 0, readBy};
}
constexpr ShadowFieldSpec intField(const char* name, int defaultValue, FieldBound low,
                                   FieldBound high, int step, unsigned readBy) {
  return {name, ShadowFieldKind::Int, {}, double(defaultValue), low, high, double(step), 0, readBy};
}
constexpr ShadowFieldSpec floatField(const char* name, float defaultValue, FieldBound low,
                                     FieldBound high, double step, int decimals, unsigned readBy) {
  return {name, ShadowFieldKind::Float, {}, defaultValue, low, high, step, decimals, readBy};
}
inline constexpr FieldBound kClampAt1{1, Bound::Clamp};
inline constexpr unsigned kMapOnly = methodBit(ShadowMethod::Map);

// The one table of the shadow fields: the nodes' constructors take their defaults from it
// (nodes/ShadowFields.h), castingSettings its clamps (nodes/DeepShadowSettings.cpp), the
// viewer's panel its ranges, and a unit test checks the nodes' FILE FORMAT blocks against it.
// A number's row: name, default, low and high end, the panel's step (and a float's decimals),
// the methods that read it.
inline constexpr ShadowFieldSpec kShadowFields[] = {
    enumField("method", enumNames("Method", kShadowMethodNames), int(ShadowMethod::Auto),
              kEveryMethod),
    intField("resolution", 512, kClampAt1, {16384, Bound::MaxTextureSize}, 64, kMapMethods),
    intField("maxLayers", 4, kClampAt1, {kMaxMapLayers, Bound::Clamp}, 1, kMapOnly),
    // Clamped whatever the method; said only where the light builds an opacity map.
    intField("slices", kDefaultOpacitySlices, kClampAt1, {kMaxOpacitySlices, Bound::Clamp}, 1,
             methodBit(ShadowMethod::OpacityMap)),
    floatField("bias", kDefaultMapBias, {0, Bound::Clamp}, {100, Bound::Panel}, 0.05, 2,
               kMapMethods),
    enumField("shadowColor", enumNames("ShadowColor", kShadowColorNames), SoDeepShadowLight::AUTO,
              kEveryMethod),
    enumField("colorModel", enumNames("ColorModel", kColorModelNames), SoDeepShadowLight::SATURATE,
              kEveryMethod),
    enumField("precision", enumNames("Precision", kPrecisionNames), SoDeepShadowLight::FLOAT,
              kMapMethods),
    enumField("filter", enumNames("Filter", kFilterNames), kDefaultMapFilter, kMapMethods),
    // Read, and clamped, only with filter PCF.
    intField("filterSize", kDefaultMapFilterSize, kClampAt1, {kMaxMapFilterSize, Bound::Clamp}, 1,
             kMapMethods),
    enumField("layerOverflow", enumNames("LayerOverflow", kLayerOverflowNames),
              SoDeepShadowLight::MERGE, kMapOnly),
    // <= 0: fitted to the casters; only a value that is not a number is replaced.
    floatField("nearRadius", -1, {-1, Bound::Panel}, {1e6, Bound::Panel}, 0.1, 3, kMapMethods),
    floatField("farRadius", -1, {-1, Bound::Panel}, {1e6, Bound::Panel}, 0.1, 3, kMapMethods),
};

constexpr const ShadowFieldSpec& shadowField(ShadowFieldId id) {
  return kShadowFields[std::size_t(id)];
}

// A field's default as the C++ type that holds it.
template <class T>
constexpr T shadowFieldDefault(ShadowFieldId id) {
  return static_cast<T>(shadowField(id).defaultValue);
}

// The table's rows are the list's fields, in its order, of the list's types.
namespace shadow_field_table {
constexpr bool sameName(const char* a, const char* b) {
  return *a == *b && (*a == '\0' || sameName(a + 1, b + 1));
}
constexpr ShadowFieldKind kindOf(const char* type) {
  return sameName(type, "SoSFEnum")    ? ShadowFieldKind::Enum
         : sameName(type, "SoSFInt32") ? ShadowFieldKind::Int
                                       : ShadowFieldKind::Float;
}
#define IVSHADOW_CHECK_ROW(type, field)                                     \
  static_assert(sameName(shadowField(ShadowFieldId::field).name, #field) && \
                shadowField(ShadowFieldId::field).kind == kindOf(#type));
IVSHADOW_SHADOW_FIELDS(IVSHADOW_CHECK_ROW)
IVSHADOW_MAP_RANGE_FIELDS(IVSHADOW_CHECK_ROW)
#undef IVSHADOW_CHECK_ROW
}  // namespace shadow_field_table
static_assert(std::size(kShadowFields) == std::size_t(ShadowFieldId::farRadius) + 1);

}  // namespace ivshadow
