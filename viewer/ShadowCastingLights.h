#pragma once

#include <Inventor/SbVec3f.h>

#include <vector>

class SbViewportRegion;
class SoDeepShadowLight;
class SoSeparator;

namespace ivshadow {

// Makes the lights of a scene cast deep shadows, so that adding shadows neither doubles the
// light (a new light beside the scene's own saturates what both reach) nor loses it:
// - every PointLight (that is not already a DeepShadowLight) is replaced, wherever it is
//   used, by a DeepShadowLight with its name, location, colour, intensity and on;
// - every SpotLight and DirectionalLight that is on gets a DeepShadowLight standing in for
//   it, inserted just after it (under the same transformation), and is switched off: a
//   spot light's stand-in sits at its location and shines every way (a cube map has no
//   cone); a directional light's sits 3 `radius` from `center` (the scene's bounding
//   sphere), against the light's direction (far enough for nearly parallel light, near
//   enough that the scene covers a good part of the map's faces). Stand-ins are named after
//   the light with "Shadow" appended.
// Unnamed lights get the names ShadowLight, ShadowLight2, ... Returns the deep shadow lights
// made, in scene order; none for a scene without such lights.
std::vector<SoDeepShadowLight*> castShadowsFromSceneLights(SoSeparator* root, const SbVec3f& center,
                                                           float radius,
                                                           const SbViewportRegion& viewport);

}  // namespace ivshadow
