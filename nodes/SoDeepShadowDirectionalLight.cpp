#include "ivshadow/SoDeepShadowDirectionalLight.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/ShadowFields.h"
#include "scene/WarnOnce.h"

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
  IVSHADOW_ADD_SHADOW_FIELDS();
}

SoDeepShadowDirectionalLight::~SoDeepShadowDirectionalLight() {
  ivshadow::forgetWarnings(this);
}
