#pragma once

// fitMapFrame, fitSlices and mapServesView are exported for their GL-free test
// (tests/unit/MapFitTest.cpp).
#include "ivshadow/Export.h"

#include <Inventor/SbVec3f.h>

#include <array>
#include <cstdint>

class SbBox3f;
class SoNode;
class SbMatrix;
class SbViewVolume;

namespace ivshadow {

class DeepShadowPass;
struct DeepShadowLightStatistics;
struct MapState;

// The MAP method of one light slot (seeds/000 §5): the map's depth range, fitted to the casters
// unless the light sets it, then the map itself.

// The corners of what the camera can show: `volume` (in world coordinates) in the group's
// coordinates, `groupToWorld` mapping those to world coordinates.
using ViewCorners = std::array<SbVec3f, 8>;
ViewCorners viewCorners(const SbViewVolume& volume, const SbMatrix& groupToWorld);

// Sets the map's frame (MapFrame) and depth range for its light: one perspective face over a
// spot light's cone (at most kMaxSpotFaceHalfAngle) or over the casters' cone (castersCone;
// narrower than a cube face), the narrower, else the cube; a directional light's orthographic face
// over the casters' bounds clipped to `view`. The range comes from the light's settings or, where
// they are not set, from the casters' bounds.
IVSHADOW_INTERNAL void fitMapFrame(MapState& map, const SbBox3f& casterBounds,
                                   const ViewCorners& view);

// The cone a point or spot light sees its casters within: the way to the centre of their
// bounding sphere and asin(radius / distance). False for a directional light, for no casters
// and for a light inside the sphere.
bool castersCone(const MapState& map, const SbBox3f& casterBounds, SbVec3f& axis, float& angle);

// Below this cone angle a map cannot tell its casters' depths apart in floats (a light 1e5
// from a glass of 0.4 blurred an opacity map's shadow, at 1e9 the deep map's too): the light
// traces its shadow rays instead, saying so once.
inline constexpr float kMinMapConeAngle = 1e-4f;

// An opacity map's sliced distances (MapState::sliceNear, sliceFar), after fitMapFrame: the
// transparent casters' distances along the map's axes, within its depth range. Opaque casters
// need no slice (their depth is kept apart), and receivers beyond the last transparent caster
// count every slice fully wherever the range ends. Radii the light sets are used as they are.
IVSHADOW_INTERNAL void fitSlices(MapState& map, const SbBox3f& transparentBounds);

// Whether a directional light's map fitted before still serves `view`: everything the view
// shows of the casters lies inside it, and it is not over three times as wide as that (the
// texels would be wasted). Other maps do not depend on the view.
IVSHADOW_INTERNAL bool mapServesView(const MapState& map, const SbBox3f& casterBounds,
                                     const ViewCorners& view);

// The memory a map build may take in the current context: what GL says it can give
// (gl/GlMemoryBudget.h), capped by IVSHADOW_GL_MEMORY_LIMIT (bytes; a value that is
// not a number above 0 is reported once and ignored); 0 when nothing says.
std::uint64_t mapMemoryBudget(bool softwareRenderer);

// Builds slot `slot`'s map as `map` asks (settings resolved, range fitted), records where its
// layers went in `map` and what it holds in `light`. A resolution whose build would need more
// than `budget` bytes (0: unknown), or that runs out of GL memory, is halved until the build
// fits, with one warning naming `light node`'s field; map.settings.resolution then holds the
// resolution built. Where even the smallest runs out, the light lights without a shadow.
void buildSlotMap(DeepShadowPass& pass, int slot, MapState& map, DeepShadowLightStatistics& light,
                  const SoNode& lightNode, std::uint64_t budget);

}  // namespace ivshadow
