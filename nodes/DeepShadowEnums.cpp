#include "nodes/DeepShadowEnums.h"

#include "ivshadow/SoDeepShadowLight.h"

#include <Inventor/fields/SoFieldData.h>

namespace ivshadow {

void addDeepShadowEnumValues(SoFieldData* fieldData) {
  fieldData->addEnumValue("ShadowColor", "AUTO", SoDeepShadowLight::AUTO);
  fieldData->addEnumValue("ShadowColor", "MONOCHROME", SoDeepShadowLight::MONOCHROME);
  fieldData->addEnumValue("ShadowColor", "COLORED", SoDeepShadowLight::COLORED);
  fieldData->addEnumValue("ColorModel", "SATURATE", SoDeepShadowLight::SATURATE);
  fieldData->addEnumValue("ColorModel", "POWER", SoDeepShadowLight::POWER);
  fieldData->addEnumValue("Precision", "FLOAT", SoDeepShadowLight::FLOAT);
  fieldData->addEnumValue("Precision", "HALF", SoDeepShadowLight::HALF);
  fieldData->addEnumValue("Filter", "NONE", SoDeepShadowLight::NONE);
  fieldData->addEnumValue("Filter", "PCF", SoDeepShadowLight::PCF);
  fieldData->addEnumValue("LayerOverflow", "MERGE", SoDeepShadowLight::MERGE);
  fieldData->addEnumValue("LayerOverflow", "TRUNCATE", SoDeepShadowLight::TRUNCATE);
  // Files say AUTO for the method too; the C++ name is AUTO_METHOD, since ShadowColor has AUTO.
  fieldData->addEnumValue("Method", "AUTO", SoDeepShadowLight::AUTO_METHOD);
  fieldData->addEnumValue("Method", "MAP", SoDeepShadowLight::MAP);
  fieldData->addEnumValue("Method", "RAYS", SoDeepShadowLight::RAYS);
  fieldData->addEnumValue("Method", "VOLUMES", SoDeepShadowLight::VOLUMES);
  fieldData->addEnumValue("Method", "OPACITY_MAP", SoDeepShadowLight::OPACITY_MAP);
}

}  // namespace ivshadow
