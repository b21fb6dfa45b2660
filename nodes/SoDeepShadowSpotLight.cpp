#include "ivshadow/SoDeepShadowSpotLight.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/DeepShadowEnums.h"

SO_NODE_SOURCE(SoDeepShadowSpotLight);

void SoDeepShadowSpotLight::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  // Coin's own classes are registered by SoDB::init, and their initClass registers them
  // again when called twice (Coin only asserts against it): a second "SpotLight" type, of
  // which the nodes already made, and Coin's classes derived from it, are not.
  if (SoSpotLight::getClassTypeId() == SoType::badType()) SoSpotLight::initClass();
  // Registered without the "So" prefix, as Coin registers its own nodes (SoDeepShadowLight).
  PRIVATE_COMMON_INIT_CODE(SoDeepShadowSpotLight, "DeepShadowSpotLight",
                           &SoDeepShadowSpotLight::createInstance, SoSpotLight);
}

SoDeepShadowSpotLight::SoDeepShadowSpotLight() {
  SO_NODE_CONSTRUCTOR(SoDeepShadowSpotLight);
  // SoDeepShadowLight's defaults.
  SO_NODE_ADD_FIELD(resolution, (512));
  SO_NODE_ADD_FIELD(maxLayers, (4));
  SO_NODE_ADD_FIELD(nearRadius, (-1.0f));
  SO_NODE_ADD_FIELD(farRadius, (-1.0f));
  SO_NODE_ADD_FIELD(bias, (1.0f));
  SO_NODE_ADD_FIELD(shadowColor, (SoDeepShadowLight::AUTO));
  SO_NODE_ADD_FIELD(colorModel, (SoDeepShadowLight::SATURATE));
  SO_NODE_ADD_FIELD(precision, (SoDeepShadowLight::FLOAT));
  SO_NODE_ADD_FIELD(filter, (SoDeepShadowLight::NONE));
  SO_NODE_ADD_FIELD(filterSize, (3));
  SO_NODE_ADD_FIELD(method, (SoDeepShadowLight::AUTO_METHOD));
  if (SO_NODE_IS_FIRST_INSTANCE()) ivshadow::addDeepShadowEnumValues(fieldData);
  SO_NODE_SET_SF_ENUM_TYPE(shadowColor, ShadowColor);
  SO_NODE_SET_SF_ENUM_TYPE(colorModel, ColorModel);
  SO_NODE_SET_SF_ENUM_TYPE(precision, Precision);
  SO_NODE_SET_SF_ENUM_TYPE(filter, Filter);
  SO_NODE_SET_SF_ENUM_TYPE(method, Method);
}

SoDeepShadowSpotLight::~SoDeepShadowSpotLight() = default;
