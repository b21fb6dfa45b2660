#pragma once

class SbViewportRegion;
class SoCamera;
class SoDeepShadowLight;
class SoSeparator;

namespace ivshadow {

// Gives a scene without deep shadows a shadow group and light: every child of `root` except
// top-level cameras moves into a new TransparentShadowGroup (DEF ShadowGroup), whose first
// child is a DeepShadowLight (DEF ShadowLight) outside the scene's bounding sphere, above it
// and towards the viewer as seen by `camera` (nullptr: above along +y), so that the shadows
// fall visibly behind and below the objects. Returns the light.
SoDeepShadowLight* wrapInShadowGroup(SoSeparator* root, const SoCamera* camera,
                                     const SbViewportRegion& viewport);

}  // namespace ivshadow
