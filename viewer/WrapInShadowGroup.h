#pragma once

class SbViewportRegion;
class SoCamera;
class SoNode;
class SoSeparator;
class SoTransparentShadowGroup;

namespace ivshadow {

// Gives a scene without deep shadows a shadow group: the children of `root` after its last
// top-level camera move into a new TransparentShadowGroup (DEF ShadowGroup) in their place, in
// which the scene's own lights cast, unchanged; the camera and what comes before it (what
// places the camera, lights fixed to the eye) stay. A group without a light turned on gets, as
// its first child, a
// DeepShadowLight (DEF ShadowLight) outside the scene's bounding sphere, above it and towards
// the viewer as seen by `camera` (nullptr: above along +y), so that the shadows fall visibly
// behind and below the objects. Returns that light, or the group when the scene's lights cast.
SoNode* wrapInShadowGroup(SoSeparator* root, const SoCamera* camera,
                          const SbViewportRegion& viewport);

// A separate, optional step after wrapInShadowGroup, for models without a floor (a chess piece
// alone cast its shadow into the void): a ground (DEF ShadowGround, a light grey square) just
// below the group's bounding box, as CAD viewers put one, that catches the shadows. "Below" is
// along the world axis nearest to `camera`'s up (+y without a camera); the square is three
// times the box's width across, so that shadows cast at a slant land on it. When `addedLight`
// (the group has the DeepShadowLight wrapInShadowGroup added, no light of the scene's own), a
// directional fill light (DEF ShadowFill, along the view) lights the sides the lamp does not
// reach, which were black, and the group's castingLights becomes DEEP_SHADOW_LIGHTS so that
// the fill casts nothing. Returns the ground.
SoNode* addShadowGround(SoTransparentShadowGroup* group, const SoCamera* camera,
                        const SbViewportRegion& viewport, bool addedLight);

}  // namespace ivshadow
