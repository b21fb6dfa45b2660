#include "ivshadow/SoDeepShadowDirectionalLight.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/DeepShadowEnums.h"

SO_NODE_SOURCE(SoDeepShadowDirectionalLight);

void SoDeepShadowDirectionalLight::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  // Coin's own classes are registered by SoDB::init, and their initClass registers them
  // again when called twice (Coin only asserts against it): a second "DirectionalLight" type, of
  // which the nodes already made, and Coin's classes derived from it, are not.
  if (SoDirectionalLight::getClassTypeId() == SoType::badType()) SoDirectionalLight::initClass();
  // Registered without the "So" prefix, as Coin registers its own nodes (SoDeepShadowLight).
  PRIVATE_COMMON_INIT_CODE(SoDeepShadowDirectionalLight, "DeepShadowDirectionalLight",
                           &SoDeepShadowDirectionalLight::createInstance, SoDirectionalLight);
}

SoDeepShadowDirectionalLight::SoDeepShadowDirectionalLight() {
  SO_NODE_CONSTRUCTOR(SoDeepShadowDirectionalLight);
  SO_NODE_ADD_FIELD(shadowColor, (SoDeepShadowLight::AUTO));
  SO_NODE_ADD_FIELD(colorModel, (SoDeepShadowLight::SATURATE));
  if (SO_NODE_IS_FIRST_INSTANCE()) ivshadow::addDeepShadowEnumValues(fieldData);
  SO_NODE_SET_SF_ENUM_TYPE(shadowColor, ShadowColor);
  SO_NODE_SET_SF_ENUM_TYPE(colorModel, ColorModel);
}

SoDeepShadowDirectionalLight::~SoDeepShadowDirectionalLight() = default;
