#pragma once

class SbBox3f;

namespace ivshadow {

class DeepShadowPass;
struct DeepShadowLightStatistics;
struct MapState;

// The MAP method of one light slot (seeds/000 §5): the map's depth range, fitted to the casters
// unless the light sets it, then the map itself.

// Sets map.nearRadius and map.farRadius from the light's settings or, where they are not set,
// from the casters' bounds seen from map.position.
void fitMapRange(MapState& map, const SbBox3f& casterBounds);

// Builds slot `slot`'s map as `map` asks (settings resolved, range fitted), records where its
// layers went in `map` and what it holds in `light`.
void buildSlotMap(DeepShadowPass& pass, int slot, MapState& map, DeepShadowLightStatistics& light);

}  // namespace ivshadow
