#pragma once

class SoFieldData;

namespace ivshadow {

// Adds the enum values of the shadow fields (ShadowColor, ColorModel, Precision, Filter,
// Method, LayerOverflow: SoDeepShadowLight's enums) to a node class's field data, so that
// SoDeepShadowLight and SoTransparentShadowGroup, whose fields of those names mean the same, read
// and write the same names. Call from the constructor on the first instance, before
// SO_NODE_SET_SF_ENUM_TYPE.
void addDeepShadowEnumValues(SoFieldData* fieldData);

}  // namespace ivshadow
