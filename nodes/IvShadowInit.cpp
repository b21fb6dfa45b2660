#include "nodes/IvShadowInit.h"

#include "nodes/SoDeepShadowLight.h"
#include "nodes/SoPeelingSeparator.h"
#include "nodes/SoTransparentShadowGroup.h"

#include <Inventor/SoDB.h>

namespace ivshadow {

void init() {
  SoDB::init();
  SoDeepShadowLight::initClass();
  SoTransparentShadowGroup::initClass();
  SoPeelingSeparator::initClass();
}

const char* version() {
  return IVSHADOW_VERSION;
}

}  // namespace ivshadow
