#include "ivshadow/IvShadowInit.h"

#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"

#include <Inventor/SoInteraction.h>

namespace ivshadow {

void init() {
  // Coin's database, node kits, selection nodes, draggers and manipulators: what SoQt::init
  // registers for the viewer, so that every command reads the same scenes (render refused a
  // Selection that view drew).
  SoInteraction::init();
  SoDeepShadowLight::initClass();
  SoDeepShadowSpotLight::initClass();
  SoDeepShadowDirectionalLight::initClass();
  SoTransparentShadowGroup::initClass();
  SoPeelingSeparator::initClass();
}

const char* version() {
  return IVSHADOW_VERSION;
}

}  // namespace ivshadow
