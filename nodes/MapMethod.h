#pragma once

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

// Sets the map's frame (MapFrame) and depth range for its light: a point light's cube, a
// spot light's one perspective face over its cone (a cone wider than kMaxSpotFaceHalfAngle:
// the cube), a directional light's orthographic face over the casters' bounds clipped to
// `view`. The range comes from the light's settings or, where they are not set, from the
// casters' bounds.
void fitMapFrame(MapState& map, const SbBox3f& casterBounds, const ViewCorners& view);

// An opacity map's sliced distances (MapState::sliceNear, sliceFar), after fitMapFrame: the
// transparent casters' distances along the map's axes, within its depth range. Opaque casters
// need no slice (their depth is kept apart), and receivers beyond the last transparent caster
// count every slice fully wherever the range ends. Radii the light sets are used as they are.
void fitSlices(MapState& map, const SbBox3f& transparentBounds);

// Whether a directional light's map fitted before still serves `view`: everything the view
// shows of the casters lies inside it, and it is not over three times as wide as that (the
// texels would be wasted). Other maps do not depend on the view.
bool mapServesView(const MapState& map, const SbBox3f& casterBounds, const ViewCorners& view);

// The memory a map build may take in the current context: what GL says it can give
// (callbacks/GlMemoryBudget.h), capped by IVSHADOW_GL_MEMORY_LIMIT (bytes; a value that is
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
