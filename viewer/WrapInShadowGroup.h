#pragma once

class SbViewportRegion;
class SoCamera;
class SoNode;
class SoSeparator;

namespace ivshadow {

// Gives a scene without deep shadows a shadow group: every child of `root` except top-level
// cameras moves into a new TransparentShadowGroup (DEF ShadowGroup), in which the scene's own
// lights cast, unchanged. A scene without a light turned on gets, as the group's first child, a
// DeepShadowLight (DEF ShadowLight) outside the scene's bounding sphere, above it and towards
// the viewer as seen by `camera` (nullptr: above along +y), so that the shadows fall visibly
// behind and below the objects. Returns that light, or the group when the scene's lights cast.
SoNode* wrapInShadowGroup(SoSeparator* root, const SoCamera* camera,
                          const SbViewportRegion& viewport);

}  // namespace ivshadow
