#include "scene/LightLimit.h"

#include "scene/SceneTriangles.h"
#include "scene/ShadowTypes.h"
#include "scene/WarnOnce.h"

#include <Inventor/errors/SoDebugError.h>

namespace ivshadow {

void warnLightsPastGlLimit(const SoNode* where, int inForce) {
  if (inForce <= kMaxGlLights || !firstWarning(where, "lights past GL's")) return;
  SoDebugError::postWarning("ivshadow",
                            "%d lights are in force at %s, and GL lights with the first %d: "
                            "the last %d light nothing, as in any Coin viewer",
                            inForce, describeNode(where).c_str(), kMaxGlLights,
                            inForce - kMaxGlLights);
}

}  // namespace ivshadow
