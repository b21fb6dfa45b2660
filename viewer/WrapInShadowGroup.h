#pragma once

class SbViewportRegion;
class SoCamera;
class SoDeepShadowLight;
class SoSeparator;

namespace ivshadow {

// Gives a scene without deep shadows a shadow group and lights: every child of `root` except
// top-level cameras moves into a new TransparentShadowGroup (DEF ShadowGroup). The scene's
// own lights are made to cast (castShadowsFromSceneLights); a scene without any gets, as the
// group's first child, a DeepShadowLight (DEF ShadowLight) outside the scene's bounding
// sphere, above it and towards the viewer as seen by `camera` (nullptr: above along +y), so
// that the shadows fall visibly behind and below the objects. Returns the first deep shadow
// light.
SoDeepShadowLight* wrapInShadowGroup(SoSeparator* root, const SoCamera* camera,
                                     const SbViewportRegion& viewport);

}  // namespace ivshadow
