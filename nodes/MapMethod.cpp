#include "nodes/MapMethod.h"

#include "callbacks/DeepShadowMap.h"
#include "callbacks/DeepShadowPass.h"
#include "callbacks/GlMemoryBudget.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "nodes/MapState.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoNode.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

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

std::uint64_t mapMemoryBudget(bool softwareRenderer) {
  std::uint64_t budget = glMemoryBudget(softwareRenderer);
  const char* text = std::getenv("IVSHADOW_GL_MEMORY_LIMIT");
  if (text == nullptr) return budget;
  char* end = nullptr;
  const long long bytes = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || bytes <= 0) {
    static bool warned = false;
    if (!warned)
      SoDebugError::postWarning("SoTransparentShadowGroup",
                                "IVSHADOW_GL_MEMORY_LIMIT is '%s', expected a number of bytes "
                                "above 0; ignored",
                                text);
    warned = true;
    return budget;
  }
  return budget == 0 ? std::uint64_t(bytes) : std::min(budget, std::uint64_t(bytes));
}

void buildSlotMap(DeepShadowPass& pass, int slot, MapState& map, DeepShadowLightStatistics& light,
                  const SoNode& lightNode, std::uint64_t budget) {
  MapRequest request;
  for (int i = 0; i < 3; ++i) request.light[i] = map.position[i];
  request.nearRadius = map.nearRadius;
  request.farRadius = map.farRadius;
  request.resolution = map.settings.resolution;
  request.layers = map.settings.maxLayers;
  request.coloured = map.coloured;
  request.halfPrecision = map.settings.halfPrecision;
  request.colourModel = map.model;
  const int asked = request.resolution;
  while (budget > 0 && request.resolution > 1 && DeepShadowMap::peakBytesFor(request) > budget)
    request.resolution /= 2;
  const int fitted = request.resolution;
  MapBuildResult built = pass.build(slot, request);
  while (built.outOfMemory && request.resolution > 1) {
    request.resolution /= 2;
    built = pass.build(slot, request);
  }
  static std::set<const SoNode*> warned;
  if ((built.outOfMemory || request.resolution != asked) && warned.insert(&lightNode).second) {
    const std::string name = lightNode.getName().getString();
    const std::string type = std::string("So") + lightNode.getTypeId().getName().getString();
    const std::string label = name.empty() ? type : type + " \"" + name + "\"";
    MapRequest wanted = request;
    wanted.resolution = asked;
    const auto megabytes = [](std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MB"; };
    if (built.outOfMemory)
      SoDebugError::postWarning(type.c_str(),
                                "%s: no deep shadow map fits in GL memory at any resolution; "
                                "it lights without a shadow",
                                label.c_str());
    else if (request.resolution != fitted)
      SoDebugError::postWarning(type.c_str(),
                                "%s: field resolution %d: GL ran out of memory building the map "
                                "at %d; using %d",
                                label.c_str(), asked, fitted, request.resolution);
    else
      SoDebugError::postWarning(
          type.c_str(),
          "%s: field resolution %d needs %s to build, more than the %s GL can give; using %d",
          label.c_str(), asked, megabytes(DeepShadowMap::peakBytesFor(wanted)).c_str(),
          budget > 0 ? megabytes(budget).c_str() : "memory", request.resolution);
  }
  map.settings.resolution = request.resolution;
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
