#pragma once

class SoNode;

namespace ivshadow {

// Says once per `where` (a group, or the first light past the limit outside groups) that
// `inForce` lights are in force where GL lights with kMaxGlLights (scene/ShadowTypes.h): Coin
// drops the lights past them, and every path of the plugin lights as Coin draws.
void warnLightsPastGlLimit(const SoNode* where, int inForce);

}  // namespace ivshadow
