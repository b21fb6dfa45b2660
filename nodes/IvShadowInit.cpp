#include "nodes/IvShadowInit.h"

#include <Inventor/SoDB.h>

namespace ivshadow {

void init() {
  SoDB::init();
}

const char* version() {
  return IVSHADOW_VERSION;
}

}  // namespace ivshadow
