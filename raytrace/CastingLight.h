#pragma once

#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

#include <Inventor/SbVec3f.h>

class SbMatrix;
class SoLight;
class SoTransparentShadowGroup;

namespace ivshadow {

// Which lights of a shadow group cast, and from where: the one answer the GL methods and the
// reference renderer both ask, so that they cannot disagree on it.
struct CastingLight {
  LightKind kind = LightKind::Point;
  // In the coordinates of `toGroup` (the group's): a point or spot light's location; for a
  // directional light, the unit direction towards the light.
  SbVec3f position;
  // A spot light's unit axis (the direction it shines in) in the same coordinates, and its
  // cutOffAngle.
  SbVec3f axis{0.0f, 0.0f, -1.0f};
  float cutOffAngle = 0.0f;
};

// Whether `light` is one of the plugin's deep shadow lights (SoDeepShadowLight,
// SoDeepShadowSpotLight, SoDeepShadowDirectionalLight): the lights that cast under
// castingLights DEEP_SHADOW_LIGHTS.
bool isDeepShadowLight(const SoLight& light);

// Whether `light` casts in `group` (its castingLights field, the light's on field, the light
// type) and, when it does, where from. A light that cannot cast (zero direction; a spot light
// whose cutOffAngle is not in (0, pi/2]; a light type other than point, spot and directional)
// lights without a shadow: one warning per light names it and says why.
IVSHADOW_INTERNAL bool castingLight(const SoLight& light, const SoTransparentShadowGroup& group,
                                    const SbMatrix& toGroup, CastingLight& out);

// How the shadow of a light with these shadowColor and colorModel fields
// (SoDeepShadowLight::ShadowColor, ::ColorModel) filters light: COLORED and MONOCHROME as set,
// AUTO coloured when some transparent caster is coloured; a coloured one by SATURATE or POWER.
// The GL path and the tracers both ask here, so they cannot resolve it differently.
IVSHADOW_INTERNAL ShadowColourModel shadowColourModel(int shadowColor, int colorModel,
                                                      bool colouredCasters);

// How the light's shadow filters light: by the shadowColor and colorModel fields it casts with
// (a deep shadow light's own, the group's for any other light, as castingSettings chooses in
// nodes/DeepShadowSettings.h).
IVSHADOW_INTERNAL ShadowColourModel castingColourModel(const SoLight& light,
                                                       const SoTransparentShadowGroup& group,
                                                       bool colouredCasters);

}  // namespace ivshadow
