#include "ivshadow/SoDeepShadowSpotLight.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/ShadowFields.h"
#include "scene/WarnOnce.h"

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
  IVSHADOW_ADD_SHADOW_FIELDS();
  IVSHADOW_ADD_MAP_RANGE_FIELDS();
}

SoDeepShadowSpotLight::~SoDeepShadowSpotLight() {
  ivshadow::forgetWarnings(this);
}
