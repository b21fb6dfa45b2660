#include "nodes/MapMethod.h"

#include "gl/DeepShadowMap.h"
#include "gl/DeepShadowPass.h"
#include "gl/GlMemoryBudget.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "nodes/MapState.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbMatrix.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoNode.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace ivshadow {
namespace {

// Distance from `point` to the box (0 inside), the largest of its distances along the axes
// (the nearest a cube face's axial depth can be) and the distance to its farthest corner.
void distanceRange(const SbBox3f& box, const SbVec3f& point, float& nearest, float& nearestAxial,
                   float& farthest) {
  const SbVec3f& low = box.getMin();
  const SbVec3f& high = box.getMax();
  float inside = 0.0f, outside = 0.0f;
  nearestAxial = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float below = std::max(low[i] - point[i], 0.0f);
    const float above = std::max(point[i] - high[i], 0.0f);
    inside += (below + above) * (below + above);
    nearestAxial = std::max(nearestAxial, below + above);
    const float corner = std::max(std::fabs(point[i] - low[i]), std::fabs(point[i] - high[i]));
    outside += corner * corner;
  }
  nearest = std::sqrt(inside);
  farthest = std::sqrt(outside);
}

}  // namespace

namespace {

glm::vec3 toGlm(const SbVec3f& v) {
  return {v[0], v[1], v[2]};
}

// The box of `points` in the coordinates of a face along `axis` (x: right, y: up, z: along
// the axis; orthographicBasis).
template <typename Points>
void boundsAlong(const glm::vec3& axis, const Points& points, glm::vec3& low, glm::vec3& high) {
  glm::vec3 right, up;
  orthographicBasis(axis, right, up);
  low = glm::vec3(std::numeric_limits<float>::max());
  high = -low;
  for (const SbVec3f& point : points) {
    const glm::vec3 p = toGlm(point);
    const glm::vec3 q(glm::dot(p, right), glm::dot(p, up), glm::dot(p, axis));
    low = glm::min(low, q);
    high = glm::max(high, q);
  }
}

std::array<SbVec3f, 8> boxCorners(const SbBox3f& box) {
  std::array<SbVec3f, 8> corners;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k)
      corners[std::size_t(i)][k] = (i >> k) & 1 ? box.getMax()[k] : box.getMin()[k];
  return corners;
}

// A directional light's rectangle (x, y across the light): what the casters cover and the
// view shows, and the casters' depth range along the light (z). No overlap: an empty
// rectangle (low > high).
void visibleCasterRectangle(const glm::vec3& axis, const SbBox3f& casterBounds,
                            const ViewCorners& view, glm::vec3& low, glm::vec3& high) {
  boundsAlong(axis, boxCorners(casterBounds), low, high);
  glm::vec3 viewLow, viewHigh;
  boundsAlong(axis, view, viewLow, viewHigh);
  // A receiver the view shows and the casters that shadow it lie on one line along the
  // light: only the view's footprint across the light matters, not its depth.
  low.x = std::max(low.x, viewLow.x);
  low.y = std::max(low.y, viewLow.y);
  high.x = std::min(high.x, viewHigh.x);
  high.y = std::min(high.y, viewHigh.y);
}

void fitDirectional(MapState& map, const SbBox3f& casterBounds, const ViewCorners& view) {
  const glm::vec3 axis = -toGlm(map.position);  // the way the light travels
  glm::vec3 low(0.0f), high(0.0f);
  if (!casterBounds.isEmpty()) {
    visibleCasterRectangle(axis, casterBounds, view, low, high);
    glm::vec3 castersLow, castersHigh;
    boundsAlong(axis, boxCorners(casterBounds), castersLow, castersHigh);
    if (low.x > high.x || low.y > high.y) {
      // Nothing the view shows is shadowed: a map of no extent, drawn over nothing.
      low = high = 0.5f * (castersLow + castersHigh);
    } else {
      // A margin of a quarter on each side, within the casters, so that a camera moving a
      // little keeps the map (mapServesView).
      const glm::vec3 margin = 0.25f * (high - low);
      low = glm::max(low - margin, castersLow);
      high = glm::min(high + margin, castersHigh);
    }
    // The casters' whole depth, a little more on either side so that none touches a plane.
    const float pad =
        0.01f * (castersHigh.z - castersLow.z) + 1e-4f * (1.0f + std::abs(castersHigh.z));
    low.z = castersLow.z - pad;
    high.z = castersHigh.z + pad;
  }
  map.coveredLow = low;
  map.coveredHigh = high;
  map.nearRadius = 0.0f;
  map.farRadius = high.z - low.z;
  map.frame = orthographicFrame(axis, low, high);
}

}  // namespace

ViewCorners viewCorners(const SbViewVolume& volume, const SbMatrix& groupToWorld) {
  SbMatrix affine, projection;
  volume.getMatrices(affine, projection);
  const SbMatrix groupToClip = groupToWorld * affine * projection;
  const SbMatrix clipToGroup = groupToClip.inverse();
  ViewCorners corners;
  for (int i = 0; i < 8; ++i) {
    const SbVec3f ndc(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
    clipToGroup.multVecMatrix(ndc, corners[std::size_t(i)]);
  }
  return corners;
}

bool castersCone(const MapState& map, const SbBox3f& casterBounds, SbVec3f& axis, float& angle) {
  if (map.kind == LightKind::Directional || casterBounds.isEmpty()) return false;
  axis = casterBounds.getCenter() - map.position;
  const float distance = axis.length();
  const float radius = 0.5f * (casterBounds.getMax() - casterBounds.getMin()).length();
  if (!(distance > radius)) return false;
  axis /= distance;
  angle = std::asin(radius / distance);
  return true;
}

void fitMapFrame(MapState& map, const SbBox3f& casterBounds, const ViewCorners& view) {
  if (map.kind == LightKind::Directional) {
    fitDirectional(map, casterBounds, view);
    return;
  }
  float nearest = 0.0f, nearestAxial = 0.0f, farthest = 1.0f;
  if (!casterBounds.isEmpty())
    distanceRange(casterBounds, map.position, nearest, nearestAxial, farthest);
  // One face over a spot light's cone, or over the cone the casters fill seen from the light,
  // whichever is narrower: a light outside its casters' bounding sphere sees them within
  // asin(radius / distance) of the way to its centre. A cube spends its texels on all
  // directions: a light 1000 units from a glass of 0.6 gave it less than a texel of the cube,
  // and its shadow vanished (issue 36). Beside the face no caster lies towards the light.
  bool oneFace = map.kind == LightKind::Spot && map.cutOffAngle <= kMaxSpotFaceHalfAngle;
  float coneAngle = oneFace ? map.cutOffAngle : 0.0f;
  glm::vec3 axis = toGlm(map.axis);
  SbVec3f castersAxis;
  float castersAngle = 0.0f;
  // Wider than a cube face (45 degrees), the face's texels would be coarser than the cube's.
  if (castersCone(map, casterBounds, castersAxis, castersAngle) &&
      castersAngle < glm::quarter_pi<float>() && (!oneFace || castersAngle < coneAngle)) {
    oneFace = true;
    coneAngle = castersAngle;
    axis = toGlm(castersAxis);
  }
  // The near plane clips by depth along the face's axis. A point in the face's cone lies at
  // least cos(coneAngle) of its distance along the axis; a cube face's depth of a point is
  // its largest coordinate from the light, which over the box is at least the largest gap
  // along an axis (a box corner seen diagonally lies 1/sqrt(3) of its distance along each).
  nearest = oneFace ? nearest * std::cos(coneAngle) : nearestAxial;
  // The map must reach past the farthest caster; the near plane may not cut off any of
  // them, and reversed floating-point depth keeps a 1e5 ratio precise.
  const float far = farthest > 0.0f ? farthest * 1.01f : 1.0f;
  map.farRadius = map.settings.farRadius > 0.0f ? map.settings.farRadius : far;
  map.nearRadius = map.settings.nearRadius > 0.0f ? map.settings.nearRadius
                                                  : std::max(nearest * 0.99f, far * 1e-5f);
  if (map.nearRadius >= map.farRadius) map.nearRadius = map.farRadius * 1e-5f;
  if (oneFace) {
    // One percent wider than the cone, so that the cone's rim and the filter's taps there
    // fall inside the face.
    const float halfAngle = std::atan(std::tan(coneAngle) * 1.01f);
    map.frame =
        perspectiveFrame(toGlm(map.position), axis, halfAngle, map.nearRadius, map.farRadius);
  } else {
    map.frame = cubeFrame(toGlm(map.position), map.nearRadius, map.farRadius);
  }
}

void fitSlices(MapState& map, const SbBox3f& transparentBounds) {
  map.sliceNear = map.nearRadius;
  map.sliceFar = map.farRadius;
  // Radii the light sets are the slices' too; without transparent casters the slices hold
  // nothing and their range does not matter.
  if (map.settings.nearRadius > 0.0f || map.settings.farRadius > 0.0f ||
      transparentBounds.isEmpty())
    return;
  // The distance the map stores, along each face's axis, over the box's corners (linear along
  // one axis, so its extremes are at corners); a cube face's is a point's largest coordinate
  // from the light, least over the box where the box is farthest off along some axis.
  const SbVec3f& low = transparentBounds.getMin();
  const SbVec3f& high = transparentBounds.getMax();
  float nearest = std::numeric_limits<float>::max(), farthest = 0.0f;
  if (map.frame.projection == MapProjection::Cube) {
    float ignored = 0.0f;
    distanceRange(transparentBounds, map.position, ignored, nearest, ignored);
    for (int i = 0; i < 3; ++i)
      farthest = std::max(
          {farthest, std::fabs(low[i] - map.position[i]), std::fabs(high[i] - map.position[i])});
  } else {
    const MapFace& face = map.frame.faces[0];
    for (const SbVec3f& corner : boxCorners(transparentBounds)) {
      const float depth = glm::dot(toGlm(corner) - face.depthOrigin, face.depthAxis);
      nearest = std::min(nearest, depth);
      farthest = std::max(farthest, depth);
    }
  }
  // A little beyond the casters either way, within the map's range, and never empty.
  const float pad = 0.01f * (farthest - nearest) + 1e-4f * (1.0f + std::fabs(farthest));
  map.sliceNear = std::max(map.nearRadius, nearest - pad);
  map.sliceFar = std::min(map.farRadius, farthest + pad);
  if (!(map.sliceFar > map.sliceNear)) {
    map.sliceNear = map.nearRadius;
    map.sliceFar = map.farRadius;
  }
}

bool mapServesView(const MapState& map, const SbBox3f& casterBounds, const ViewCorners& view) {
  if (map.kind != LightKind::Directional || casterBounds.isEmpty()) return true;
  glm::vec3 low, high;
  visibleCasterRectangle(-toGlm(map.position), casterBounds, view, low, high);
  if (low.x > high.x || low.y > high.y) return true;  // nothing visible is shadowed
  // Rounding: a rectangle fitted from the same view must serve it.
  const glm::vec2 slack = 1e-4f * (glm::vec2(map.coveredHigh - map.coveredLow) + 1e-3f);
  const bool inside = low.x >= map.coveredLow.x - slack.x && low.y >= map.coveredLow.y - slack.y &&
                      high.x <= map.coveredHigh.x + slack.x &&
                      high.y <= map.coveredHigh.y + slack.y;
  const float needed = std::max(high.x - low.x, high.y - low.y);
  const float covered =
      std::max(map.coveredHigh.x - map.coveredLow.x, map.coveredHigh.y - map.coveredLow.y);
  return inside && 3.0f * needed >= covered;
}

std::uint64_t mapMemoryBudget(bool softwareRenderer) {
  std::uint64_t budget = glMemoryBudget(softwareRenderer);
  const char* text = std::getenv("IVSHADOW_GL_MEMORY_LIMIT");
  if (text == nullptr) return budget;
  char* end = nullptr;
  const long long bytes = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || bytes <= 0) {
    if (firstWarning(nullptr, "IVSHADOW_GL_MEMORY_LIMIT"))
      SoDebugError::postWarning("SoTransparentShadowGroup",
                                "IVSHADOW_GL_MEMORY_LIMIT is '%s', expected a number of bytes "
                                "above 0; ignored",
                                text);
    return budget;
  }
  return budget == 0 ? std::uint64_t(bytes) : std::min(budget, std::uint64_t(bytes));
}

namespace {

// What slot `map` asks of the build, its resolution halved until the build fits `budget`
// bytes (0: unknown).
MapRequest mapRequest(const MapState& map, std::uint64_t budget) {
  MapRequest request;
  request.frame = map.frame;
  request.resolution = map.settings.resolution;
  request.layers = map.settings.maxLayers;
  request.coloured = map.coloured;
  request.halfPrecision = map.settings.halfPrecision;
  request.colourModel = map.model;
  request.mergeOverflow = map.settings.mergeOverflow;
  if (map.method == ShadowMethod::OpacityMap) {
    request.slices = map.settings.slices;
    request.sliceNear = map.sliceNear;
    request.sliceFar = map.sliceFar;
  }
  while (budget > 0 && request.resolution > 1 && DeepShadowPass::peakBytesFor(request) > budget)
    request.resolution /= 2;
  // The lists may take what the budget leaves beside the layers; a map that needs more is
  // built layer by layer. At least one byte: 0 would mean no limit.
  if (budget > 0)
    request.listByteLimit = std::max<std::uint64_t>(
        budget - std::min(budget, DeepShadowPass::peakBytesFor(request)), 1u);
  return request;
}

// How the warnings name the light node: its class, and its name where it has one.
struct LightLabel {
  explicit LightLabel(const SoNode& node)
      : type(std::string("So") + node.getTypeId().getName().getString()) {
    const std::string name = node.getName().getString();
    label = name.empty() ? type : type + " \"" + name + "\"";
  }
  std::string type;
  std::string label;
};

// Says, once, why a build made nothing at all: the program is the same for every light and
// group, so its failure is said once per process; another failure (GL could not allocate what
// a map of any size needs) once per light.
void warnNothingBuilt(const DeepShadowPass& pass, const MapRequest& request, const MapState& map,
                      const MapBuildResult& built, const SoNode& lightNode) {
  const bool opacity = map.method == ShadowMethod::OpacityMap;
  if (built.noProgram && firstWarning(nullptr, opacity ? "opacity map program" : "map program"))
    SoDebugError::postWarning("SoTransparentShadowGroup",
                              "%s; lights with method %s light "
                              "without a shadow",
                              pass.programError(request).c_str(), shadowMethodName(map.method));
  const LightLabel light(lightNode);
  if (!built.noProgram && firstWarning(&lightNode, "map failure"))
    SoDebugError::postWarning(light.type.c_str(), "%s: %s; it lights without a shadow",
                              light.label.c_str(), built.failure.c_str());
}

// Says, once per light, that the map was built at a smaller resolution than `asked` (the
// budget's `fitted`, or smaller where GL ran out of memory), or not at all.
void warnResolution(const MapRequest& request, const MapBuildResult& built, bool opacity, int asked,
                    int fitted, std::uint64_t budget, const SoNode& lightNode) {
  if (!(built.outOfMemory || request.resolution != asked) ||
      !firstWarning(&lightNode, "map resolution"))
    return;
  const LightLabel light(lightNode);
  MapRequest wanted = request;
  wanted.resolution = asked;
  const auto megabytes = [](std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MB"; };
  if (built.outOfMemory)
    SoDebugError::postWarning(light.type.c_str(),
                              "%s: no %s fits in GL memory at any resolution; "
                              "it lights without a shadow",
                              light.label.c_str(), opacity ? "opacity map" : "deep shadow map");
  else if (request.resolution != fitted)
    SoDebugError::postWarning(light.type.c_str(),
                              "%s: field resolution %d: GL ran out of memory building the map "
                              "at %d; using %d",
                              light.label.c_str(), asked, fitted, request.resolution);
  else
    SoDebugError::postWarning(
        light.type.c_str(),
        "%s: field resolution %d needs %s to build, more than the %s GL can give; using %d",
        light.label.c_str(), asked, megabytes(DeepShadowPass::peakBytesFor(wanted)).c_str(),
        budget > 0 ? megabytes(budget).c_str() : "memory", request.resolution);
}

// What the built map holds, for the statistics.
void recordBuild(const DeepShadowPass& pass, int slot, const MapState& map,
                 const MapRequest& request, const MapBuildResult& built,
                 DeepShadowLightStatistics& light) {
  light.layersUsed = built.layersUsed;
  light.passes = built.passes;
  light.mapBuild = built.fragmentLists ? "FRAGMENT_LISTS" : "PEELING";
  light.listFragments = built.listFragments;
  light.mergedTexels = built.mergedTexels;
  light.mergeError = built.mergeError;
  light.bytes = pass.mapBytes(slot);
  light.peakBytes = pass.mapPeakBytes(slot);
  light.resolution = request.resolution;
  light.projection = map.frame.projection == MapProjection::Cube          ? "CUBE"
                     : map.frame.projection == MapProjection::Perspective ? "PERSPECTIVE"
                                                                          : "ORTHOGRAPHIC";
  if (map.frame.projection == MapProjection::Orthographic)
    light.extent = {map.coveredHigh.x - map.coveredLow.x, map.coveredHigh.y - map.coveredLow.y};
  light.nearRadius = map.nearRadius;
  light.farRadius = map.farRadius;
}

}  // namespace

void buildSlotMap(DeepShadowPass& pass, int slot, MapState& map, DeepShadowLightStatistics& light,
                  const SoNode& lightNode, std::uint64_t budget) {
  const int asked = map.settings.resolution;
  MapRequest request = mapRequest(map, budget);
  const int fitted = request.resolution;
  MapBuildResult built = pass.build(slot, request);
  if (built.noProgram || !built.failure.empty()) {
    warnNothingBuilt(pass, request, map, built, lightNode);
    map.faceLayers = {};
    light.resolution = 0;
    return;
  }
  while (built.outOfMemory && request.resolution > 1) {
    request.resolution /= 2;
    built = pass.build(slot, request);
  }
  if (!built.failure.empty()) built.outOfMemory = true;  // appeared at a smaller size only
  warnResolution(request, built, map.method == ShadowMethod::OpacityMap, asked, fitted, budget,
                 lightNode);
  // A map that the fragment lists could not hold was built layer by layer:
  // the same map, one draw per layer, but for the surfaces past maxLayers, which that build
  // cannot merge. Said once per reason: a context without the lists gives every light the
  // same one.
  if (!built.listFailure.empty() && !built.outOfMemory &&
      firstWarning(nullptr, "map lists: " + built.listFailure)) {
    const LightLabel label(lightNode);
    SoDebugError::postWarning(label.type.c_str(),
                              "%s: %s; its map is built by depth peeling instead%s",
                              label.label.c_str(), built.listFailure.c_str(),
                              request.mergeOverflow ? ", which keeps only the nearest maxLayers "
                                                      "surfaces of a texel (layerOverflow TRUNCATE)"
                                                    : "");
  }
  map.settings.resolution = request.resolution;
  map.faceFirst = built.firstLayer;
  map.faceLayers = built.layersUsed;
  recordBuild(pass, slot, map, request, built, light);
}

}  // namespace ivshadow
