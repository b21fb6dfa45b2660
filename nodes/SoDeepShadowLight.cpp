#include "ivshadow/SoDeepShadowLight.h"

#include "nodes/DeepShadowEnums.h"

SO_NODE_SOURCE(SoDeepShadowLight);

void SoDeepShadowLight::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  SoPointLight::initClass();
  // Registered without the "So" prefix, as Coin registers its own nodes: Coin writes that
  // name to files, and SoType::fromName finds "DeepShadowLight" from either spelling.
  PRIVATE_COMMON_INIT_CODE(SoDeepShadowLight, "DeepShadowLight", &SoDeepShadowLight::createInstance,
                           SoPointLight);
}

SoDeepShadowLight::SoDeepShadowLight() {
  SO_NODE_CONSTRUCTOR(SoDeepShadowLight);
  SO_NODE_ADD_FIELD(resolution, (512));
  SO_NODE_ADD_FIELD(maxLayers, (4));
  SO_NODE_ADD_FIELD(nearRadius, (-1.0f));
  SO_NODE_ADD_FIELD(farRadius, (-1.0f));
  SO_NODE_ADD_FIELD(bias, (1.0f));
  SO_NODE_ADD_FIELD(shadowColor, (AUTO));
  SO_NODE_ADD_FIELD(colorModel, (SATURATE));
  SO_NODE_ADD_FIELD(precision, (FLOAT));
  SO_NODE_ADD_FIELD(filter, (NONE));
  SO_NODE_ADD_FIELD(filterSize, (3));
  SO_NODE_ADD_FIELD(method, (AUTO_METHOD));

  if (SO_NODE_IS_FIRST_INSTANCE()) ivshadow::addDeepShadowEnumValues(fieldData);
  SO_NODE_SET_SF_ENUM_TYPE(shadowColor, ShadowColor);
  SO_NODE_SET_SF_ENUM_TYPE(colorModel, ColorModel);
  SO_NODE_SET_SF_ENUM_TYPE(precision, Precision);
  SO_NODE_SET_SF_ENUM_TYPE(filter, Filter);
  SO_NODE_SET_SF_ENUM_TYPE(method, Method);
}

SoDeepShadowLight::~SoDeepShadowLight() = default;
