#pragma once

#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

class SoDeepShadowLight;
class SoTransparentShadowGroup;

namespace ivshadow {

// The fields of a SoDeepShadowLight after clamping to what the map builder accepts.
struct DeepShadowSettings {
  int resolution = 512;
  int maxLayers = 4;
  float nearRadius = -1.0f;  // <= 0: fitted to the casters
  float farRadius = -1.0f;   // <= 0: fitted to the casters
  float bias = 1.0f;
  int shadowColor = 0;  // SoDeepShadowLight::ShadowColor
  int colorModel = 0;   // SoDeepShadowLight::ColorModel
  bool halfPrecision = false;
  int filterRadius = 0;  // 0 = nearest texel, r = (2r+1)^2 taps
  int method = 0;        // SoDeepShadowLight::Method as set (AUTO not yet resolved)
};

// Reads and clamps the light's fields; each field that is out of range is reported once per
// light through SoDebugError::postWarning, naming the node and the field.
IVSHADOW_INTERNAL DeepShadowSettings resolveSettings(SoDeepShadowLight& light, int maxTextureSize);
// The same for the group's fields, which ordinary lights in it cast with (radii fitted).
IVSHADOW_INTERNAL DeepShadowSettings resolveSettings(SoTransparentShadowGroup& group,
                                                     int maxTextureSize);

// How the shadow of a light with these shadowColor and colorModel fields
// (SoDeepShadowLight::ShadowColor, ::ColorModel) filters light: COLORED and MONOCHROME as set,
// AUTO coloured when some transparent caster is coloured; a coloured one by SATURATE or POWER.
// The GL path and the reference both ask here, so they cannot resolve it differently.
IVSHADOW_INTERNAL ShadowColourModel shadowColourModel(int shadowColor, int colorModel,
                                                      bool colouredCasters);

}  // namespace ivshadow
