#include "ivshadow/IvShadowInit.h"

#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"

#include <Inventor/SoDB.h>

namespace ivshadow {

void init() {
  SoDB::init();
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
