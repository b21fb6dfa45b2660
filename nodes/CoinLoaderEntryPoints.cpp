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
#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"

// Declared and defined out of line, and marked for export (the library hides everything
// else), so that each is a function of the library that Coin can look up by name.
struct IVSHADOW_API TransparentShadowGroup {
  static void initClass();
};
struct IVSHADOW_API DeepShadowLight {
  static void initClass();
};
struct IVSHADOW_API PeelingSeparator {
  static void initClass();
};
struct IVSHADOW_API DeepShadowSpotLight {
  static void initClass();
};
struct IVSHADOW_API DeepShadowDirectionalLight {
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
void DeepShadowSpotLight::initClass() {
  SoDeepShadowSpotLight::initClass();
}
void DeepShadowDirectionalLight::initClass() {
  SoDeepShadowDirectionalLight::initClass();
}
