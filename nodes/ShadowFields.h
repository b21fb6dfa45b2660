#pragma once

#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/DeepShadowEnums.h"
#include "nodes/DeepShadowSettings.h"

namespace ivshadow {
// The map's depth offset towards the light, in texels at the receiver, beyond the receiver's
// own plane (lighting.glsl). The lookup compares the stored surfaces with that plane, so the
// offset covers only float rounding; a tenth of a texel was the most accurate on the bundled
// scenes (docs/TRADEOFF.md, "Bias"), and light can leak only where a caster lies that close.
constexpr float kDefaultMapBias = 0.1f;
// Bilinear PCF: the visibility of the four texels around the point, weighted by their
// overlap with one texel's square. It was 0.7 to 1.3 dB nearer the exact picture than the
// nearest texel on every bundled scene of the trade, and a 3 x 3 square farther
// (docs/TRADEOFF.md, "Defaults").
constexpr SoDeepShadowLight::Filter kDefaultMapFilter = SoDeepShadowLight::PCF;
constexpr int kDefaultMapFilterSize = 1;
}  // namespace ivshadow

// The shadow fields that SoDeepShadowLight, SoDeepShadowSpotLight, SoDeepShadowDirectionalLight
// and SoTransparentShadowGroup share, with SoDeepShadowLight's defaults and enum types, added
// in a node's constructor after SO_NODE_CONSTRUCTOR. A macro, because Coin's
// SO_NODE_ADD_FIELD, which it wraps, works only in the scope of the node's constructor.
#define IVSHADOW_ADD_SHADOW_FIELDS()                                               \
  do {                                                                             \
    SO_NODE_ADD_FIELD(method, (SoDeepShadowLight::AUTO_METHOD));                   \
    SO_NODE_ADD_FIELD(resolution, (512));                                          \
    SO_NODE_ADD_FIELD(maxLayers, (4));                                             \
    SO_NODE_ADD_FIELD(slices, (ivshadow::kDefaultOpacitySlices));                  \
    SO_NODE_ADD_FIELD(bias, (ivshadow::kDefaultMapBias));                          \
    SO_NODE_ADD_FIELD(shadowColor, (SoDeepShadowLight::AUTO));                     \
    SO_NODE_ADD_FIELD(colorModel, (SoDeepShadowLight::SATURATE));                  \
    SO_NODE_ADD_FIELD(precision, (SoDeepShadowLight::FLOAT));                      \
    SO_NODE_ADD_FIELD(filter, (ivshadow::kDefaultMapFilter));                      \
    SO_NODE_ADD_FIELD(filterSize, (ivshadow::kDefaultMapFilterSize));              \
    SO_NODE_ADD_FIELD(layerOverflow, (SoDeepShadowLight::MERGE));                  \
    if (SO_NODE_IS_FIRST_INSTANCE()) ivshadow::addDeepShadowEnumValues(fieldData); \
    SO_NODE_SET_SF_ENUM_TYPE(method, Method);                                      \
    SO_NODE_SET_SF_ENUM_TYPE(shadowColor, ShadowColor);                            \
    SO_NODE_SET_SF_ENUM_TYPE(colorModel, ColorModel);                              \
    SO_NODE_SET_SF_ENUM_TYPE(precision, Precision);                                \
    SO_NODE_SET_SF_ENUM_TYPE(filter, Filter);                                      \
    SO_NODE_SET_SF_ENUM_TYPE(layerOverflow, LayerOverflow);                        \
  } while (false)
