#pragma once

#include "ivshadow/Export.h"
#include "ivshadow/ShadowMethod.h"
#include "nodes/ShadowFieldTable.h"
#include "scene/ShadowTypes.h"

class SoDeepShadowDirectionalLight;
class SoDeepShadowLight;
class SoDeepShadowSpotLight;
class SoLight;
class SoTransparentShadowGroup;

namespace ivshadow {

// One bounce of the group's casting lights (SoTransparentShadowGroup::bounce, seeds/001): the
// defaults are the document's, 256 virtual point lights with 128 x 128 imperfect shadow maps.
inline constexpr int kDefaultBounceLights = 256;
inline constexpr int kMaxBounceLights = 1024;
inline constexpr int kDefaultBounceMapSize = 128;
inline constexpr int kMinBounceMapSize = 16;
inline constexpr int kMaxBounceMapSize = 256;

// The group's bounce fields after clamping (the map size to a power of two, so that the
// atlas's tiles stay apart through the pull-push levels).
struct BounceSettings {
  bool on = false;
  int lights = kDefaultBounceLights;
  int mapSize = kDefaultBounceMapSize;
};
// Reads and clamps them, each field out of range reported once, as resolveSettings does.
IVSHADOW_INTERNAL BounceSettings resolveBounce(SoTransparentShadowGroup& group);

// The fraction of the viewport's width and height a traced group traces at while it moves
// (SoTransparentShadowGroup::movingResolution), and how long it waits for stillness before
// tracing the full picture.
inline constexpr float kMinMovingResolution = 0.125f;
inline constexpr double kRefineDelaySeconds = 0.25;
// Reads and clamps it to kMinMovingResolution .. 1, a value outside reported once.
IVSHADOW_INTERNAL float resolveMovingResolution(SoTransparentShadowGroup& group);

// The fields of a SoDeepShadowLight after clamping to what the map builder accepts; a fresh one
// holds the fields' defaults.
struct DeepShadowSettings {
  int resolution = shadowFieldDefault<int>(ShadowFieldId::resolution);
  int maxLayers = shadowFieldDefault<int>(ShadowFieldId::maxLayers);
  int slices = shadowFieldDefault<int>(ShadowFieldId::slices);  // an opacity map's
  // <= 0: fitted to the casters
  float nearRadius = shadowFieldDefault<float>(ShadowFieldId::nearRadius);
  float farRadius = shadowFieldDefault<float>(ShadowFieldId::farRadius);
  float bias = shadowFieldDefault<float>(ShadowFieldId::bias);
  int shadowColor = shadowFieldDefault<int>(ShadowFieldId::shadowColor);  // SoDeepShadowLight's
  int colorModel = shadowFieldDefault<int>(ShadowFieldId::colorModel);    // enums
  bool halfPrecision = false;
  // 0: the nearest texel; w: the mean over a w x w texel square (PCF, lighting.glsl)
  int filterWidth = 0;
  // As set (Auto not yet resolved).
  ShadowMethod method = shadowFieldDefault<ShadowMethod>(ShadowFieldId::method);
  bool mergeOverflow = true;  // layerOverflow MERGE
};

// Reads and clamps the light's fields; each field that is out of range is reported once per
// light through SoDebugError::postWarning, naming the node and the field.
IVSHADOW_INTERNAL DeepShadowSettings resolveSettings(SoDeepShadowLight& light, int maxTextureSize);
// The same for the group's fields, which ordinary lights in it cast with (radii fitted).
IVSHADOW_INTERNAL DeepShadowSettings resolveSettings(SoTransparentShadowGroup& group,
                                                     int maxTextureSize);
// The settings `light` casts with in `group`: its own fields for a SoDeepShadowLight,
// SoDeepShadowSpotLight or SoDeepShadowDirectionalLight (the latter's colour fields over the
// group's others), the group's for any other light.
IVSHADOW_INTERNAL DeepShadowSettings castingSettings(SoLight& light,
                                                     SoTransparentShadowGroup& group,
                                                     int maxTextureSize);

}  // namespace ivshadow
