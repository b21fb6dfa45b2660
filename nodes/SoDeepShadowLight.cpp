#include "ivshadow/SoDeepShadowLight.h"

#include "nodes/ShadowFields.h"
#include "scene/WarnOnce.h"

SO_NODE_SOURCE(SoDeepShadowLight);

void SoDeepShadowLight::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  // Coin's own classes are registered by SoDB::init, and their initClass registers them
  // again when called twice (Coin only asserts against it): a second "PointLight" type, of
  // which the nodes already made, and Coin's classes derived from it, are not.
  if (SoPointLight::getClassTypeId() == SoType::badType()) SoPointLight::initClass();
  // Registered without the "So" prefix, as Coin registers its own nodes: Coin writes that
  // name to files, and SoType::fromName finds "DeepShadowLight" from either spelling.
  PRIVATE_COMMON_INIT_CODE(SoDeepShadowLight, "DeepShadowLight", &SoDeepShadowLight::createInstance,
                           SoPointLight);
}

SoDeepShadowLight::SoDeepShadowLight() {
  SO_NODE_CONSTRUCTOR(SoDeepShadowLight);
  IVSHADOW_ADD_SHADOW_FIELDS();
  IVSHADOW_ADD_MAP_RANGE_FIELDS();
}

SoDeepShadowLight::~SoDeepShadowLight() {
  ivshadow::forgetWarnings(this);
}
