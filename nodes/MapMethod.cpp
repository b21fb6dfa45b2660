#include "nodes/MapMethod.h"

#include "callbacks/DeepShadowPass.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "nodes/MapState.h"

#include <Inventor/SbBox3f.h>

#include <algorithm>
#include <cmath>

namespace ivshadow {
namespace {

// Distance from `point` to the box (0 inside) and to its farthest corner.
void distanceRange(const SbBox3f& box, const SbVec3f& point, float& nearest, float& farthest) {
  const SbVec3f& low = box.getMin();
  const SbVec3f& high = box.getMax();
  float inside = 0.0f, outside = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float below = std::max(low[i] - point[i], 0.0f);
    const float above = std::max(point[i] - high[i], 0.0f);
    inside += (below + above) * (below + above);
    const float corner = std::max(std::fabs(point[i] - low[i]), std::fabs(point[i] - high[i]));
    outside += corner * corner;
  }
  nearest = std::sqrt(inside);
  farthest = std::sqrt(outside);
}

}  // namespace

void fitMapRange(MapState& map, const SbBox3f& casterBounds) {
  float nearest = 0.0f, farthest = 1.0f;
  if (!casterBounds.isEmpty()) distanceRange(casterBounds, map.position, nearest, farthest);
  // The map must reach past the farthest caster; the near plane may not cut off any of
  // them, and reversed floating-point depth keeps a 1e5 ratio precise.
  const float far = farthest > 0.0f ? farthest * 1.01f : 1.0f;
  map.farRadius = map.settings.farRadius > 0.0f ? map.settings.farRadius : far;
  map.nearRadius = map.settings.nearRadius > 0.0f ? map.settings.nearRadius
                                                  : std::max(nearest * 0.99f, far * 1e-5f);
  if (map.nearRadius >= map.farRadius) map.nearRadius = map.farRadius * 1e-5f;
}

void buildSlotMap(DeepShadowPass& pass, int slot, MapState& map, DeepShadowLightStatistics& light) {
  MapRequest request;
  for (int i = 0; i < 3; ++i) request.light[i] = map.position[i];
  request.nearRadius = map.nearRadius;
  request.farRadius = map.farRadius;
  request.resolution = map.settings.resolution;
  request.layers = map.settings.maxLayers;
  request.coloured = map.coloured;
  request.halfPrecision = map.settings.halfPrecision;
  request.colourModel = map.model;
  const MapBuildResult built = pass.build(slot, request);
  map.faceFirst = built.firstLayer;
  map.faceLayers = built.layersUsed;

  light.layersUsed = built.layersUsed;
  light.passes = built.passes;
  light.bytes = pass.mapBytes(slot);
  light.peakBytes = pass.mapPeakBytes(slot);
  light.resolution = request.resolution;
  light.nearRadius = map.nearRadius;
  light.farRadius = map.farRadius;
}

}  // namespace ivshadow
