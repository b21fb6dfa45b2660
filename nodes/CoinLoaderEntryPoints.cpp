// Entry points for Coin's loading of unknown node classes (SoType::fromName, BRIEF §4).
//
// Reading "TransparentShadowGroup { ... }" in an application that was never linked against
// the plugin, Coin looks for a library named libTransparentShadowGroup.so and calls the
// C++ function TransparentShadowGroup::initClass() in it; for the spelling
// "SoTransparentShadowGroup" it looks for libSoTransparentShadowGroup.so and
// SoTransparentShadowGroup::initClass(). The build and the install put links under all those
// names to the plugin library; the So-prefixed functions are the nodes' own, and the
// unprefixed ones below forward to them. Each registers the node (without the prefix, as
// Coin's own nodes are registered), so both spellings then resolve to the same type.
#include "nodes/SoDeepShadowLight.h"
#include "nodes/SoPeelingSeparator.h"
#include "nodes/SoTransparentShadowGroup.h"

// Declared and defined out of line so that each is an exported function of the library.
struct TransparentShadowGroup {
  static void initClass();
};
struct DeepShadowLight {
  static void initClass();
};
struct PeelingSeparator {
  static void initClass();
};

void TransparentShadowGroup::initClass() {
  SoTransparentShadowGroup::initClass();
}
void DeepShadowLight::initClass() {
  SoDeepShadowLight::initClass();
}
void PeelingSeparator::initClass() {
  SoPeelingSeparator::initClass();
}
