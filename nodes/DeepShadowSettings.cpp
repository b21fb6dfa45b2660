#include "nodes/DeepShadowSettings.h"

#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/ShadowFieldTable.h"
#include "scene/WarnOnce.h"

#include <Inventor/errors/SoDebugError.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace ivshadow {
namespace {

// "SoDeepShadowLight \"Lamp\"", "SoTransparentShadowGroup": the class as Coin's messages
// name it, and the node's name when it has one.
std::string nodeClass(const SoNode& node) {
  return std::string("So") + node.getTypeId().getName().getString();
}

std::string nodeLabel(const SoNode& node) {
  const SbName name = node.getName();
  return name.getLength() > 0 ? nodeClass(node) + " \"" + name.getString() + "\"" : nodeClass(node);
}

void warnOnce(const SoNode& light, const char* field, const std::string& what) {
  if (!firstWarning(&light, field)) return;
  SoDebugError::postWarning(nodeClass(light).c_str(), "%s: field %s %s", nodeLabel(light).c_str(),
                            field, what.c_str());
}

int clampInt(const SoNode& light, const char* field, int value, int low, int high) {
  if (value >= low && value <= high) return value;
  const int clamped = std::clamp(value, low, high);
  warnOnce(light, field,
           "is " + std::to_string(value) + ", outside " + std::to_string(low) + ".." +
               std::to_string(high) + "; using " + std::to_string(clamped));
  return clamped;
}

float finiteOr(const SoNode& light, const char* field, float value, float fallback) {
  if (std::isfinite(value)) return value;
  std::ostringstream text;
  text << "is not a finite number; using " << fallback;
  warnOnce(light, field, text.str());
  return fallback;
}

// The table's number fields clamp as the messages below say: an integer at both ends (a
// resolution's high end is GL's largest texture), a float at most below, at 0.
constexpr bool tableClampsAsSaid() {
  for (const ShadowFieldSpec& f : kShadowFields) {
    if (f.kind == ShadowFieldKind::Int &&
        (f.low.kind != Bound::Clamp || f.high.kind == Bound::Panel))
      return false;
    if (f.kind == ShadowFieldKind::Float &&
        ((f.low.kind == Bound::Clamp && f.low.value != 0.0) || f.high.kind != Bound::Panel))
      return false;
  }
  return true;
}
static_assert(tableClampsAsSaid());

// An integer field within the table's range, said once per node and field when `say` (a field
// the light's method does not read is clamped quietly).
int tableInt(const SoNode& node, ShadowFieldId id, int value, int maxTextureSize, bool say = true) {
  const ShadowFieldSpec& f = shadowField(id);
  const int low = int(f.low.value);
  const int high =
      f.high.kind == Bound::MaxTextureSize ? std::max(1, maxTextureSize) : int(f.high.value);
  return say ? clampInt(node, f.name, value, low, high) : std::clamp(value, low, high);
}

// A float field: not a finite number, its default; below the table's low end, where that
// clamps (bias), 0.
float tableFloat(const SoNode& node, ShadowFieldId id, float value) {
  const ShadowFieldSpec& f = shadowField(id);
  value = finiteOr(node, f.name, value, float(f.defaultValue));
  if (f.low.kind == Bound::Clamp && value < float(f.low.value)) {
    warnOnce(node, f.name, "is negative; using 0");
    value = float(f.low.value);
  }
  return value;
}

// The map's radii: a light's nearRadius and farRadius fields; a group's ordinary lights fit
// them.
template <class Light>
void readRadii(const Light& light, DeepShadowSettings& s) {
  s.nearRadius = tableFloat(light, ShadowFieldId::nearRadius, light.nearRadius.getValue());
  s.farRadius = tableFloat(light, ShadowFieldId::farRadius, light.farRadius.getValue());
  if (s.nearRadius > 0.0f && s.farRadius > 0.0f && s.nearRadius >= s.farRadius) {
    warnOnce(light, "nearRadius", "is not below farRadius; fitting both to the casters");
    s.nearRadius = s.farRadius = -1.0f;
  }
}

// A group's ordinary lights and a directional light's map fit their range to the casters.
void readRadii(const SoTransparentShadowGroup&, DeepShadowSettings&) {}
void readRadii(const SoDeepShadowDirectionalLight&, DeepShadowSettings&) {}

// SoDeepShadowLight and SoTransparentShadowGroup have the shadow fields under the same names.
template <class Node>
DeepShadowSettings resolveFields(Node& light, int maxTextureSize) {
  DeepShadowSettings s;
  s.resolution =
      tableInt(light, ShadowFieldId::resolution, light.resolution.getValue(), maxTextureSize);
  s.maxLayers =
      tableInt(light, ShadowFieldId::maxLayers, light.maxLayers.getValue(), maxTextureSize);
  // Only a light that builds an opacity map (or may, as a group's ordinary lights with the
  // group's method) is told about its slices; the others keep them clamped, unused.
  s.slices = tableInt(light, ShadowFieldId::slices, light.slices.getValue(), maxTextureSize,
                      light.method.getValue() == SoDeepShadowLight::OPACITY_MAP);
  readRadii(light, s);
  s.bias = tableFloat(light, ShadowFieldId::bias, light.bias.getValue());
  s.shadowColor = light.shadowColor.getValue();
  s.colorModel = light.colorModel.getValue();
  s.halfPrecision = light.precision.getValue() == SoDeepShadowLight::HALF;
  if (light.filter.getValue() == SoDeepShadowLight::PCF) {
    s.filterWidth =
        tableInt(light, ShadowFieldId::filterSize, light.filterSize.getValue(), maxTextureSize);
  }
  // A value that no name spells (set from C++) builds a map, as MAP does.
  const int method = light.method.getValue();
  s.method = method >= 0 && std::size_t(method) < kShadowMethodCount ? ShadowMethod(method)
                                                                     : ShadowMethod::Map;
  s.mergeOverflow = light.layerOverflow.getValue() != SoDeepShadowLight::TRUNCATE;
  return s;
}

}  // namespace

DeepShadowSettings resolveSettings(SoDeepShadowLight& light, int maxTextureSize) {
  return resolveFields(light, maxTextureSize);
}

DeepShadowSettings resolveSettings(SoTransparentShadowGroup& group, int maxTextureSize) {
  return resolveFields(group, maxTextureSize);
}

float resolveMovingResolution(SoTransparentShadowGroup& group) {
  const float value = group.movingResolution.getValue();
  if (value >= kMinMovingResolution && value <= 1.0f) return value;
  const float clamped = std::isfinite(value) ? std::clamp(value, kMinMovingResolution, 1.0f) : 1.0f;
  std::ostringstream text;
  text << "is " << value << ", outside " << kMinMovingResolution << "..1; using " << clamped;
  warnOnce(group, "movingResolution", text.str());
  return clamped;
}

DeepShadowSettings castingSettings(SoLight& light, SoTransparentShadowGroup& group,
                                   int maxTextureSize) {
  if (light.isOfType(SoDeepShadowLight::getClassTypeId()))
    return resolveFields(static_cast<SoDeepShadowLight&>(light), maxTextureSize);
  if (light.isOfType(SoDeepShadowSpotLight::getClassTypeId()))
    return resolveFields(static_cast<SoDeepShadowSpotLight&>(light), maxTextureSize);
  if (light.isOfType(SoDeepShadowDirectionalLight::getClassTypeId()))
    return resolveFields(static_cast<SoDeepShadowDirectionalLight&>(light), maxTextureSize);
  return resolveFields(group, maxTextureSize);
}

BounceSettings resolveBounce(SoTransparentShadowGroup& group) {
  BounceSettings s;
  s.on = group.bounce.getValue() == TRUE;
  // Only a group that bounces is told about the other two.
  const auto clamp = [&](const char* field, int value, int low, int high) {
    return s.on ? clampInt(group, field, value, low, high) : std::clamp(value, low, high);
  };
  s.lights = clamp("bounceLights", group.bounceLights.getValue(), 1, kMaxBounceLights);
  const int size =
      clamp("bounceMapSize", group.bounceMapSize.getValue(), kMinBounceMapSize, kMaxBounceMapSize);
  s.mapSize = kMinBounceMapSize;
  while (s.mapSize * 2 <= size) s.mapSize *= 2;
  if (s.on && s.mapSize != size)
    warnOnce(
        group, "bounceMapSize",
        "is " + std::to_string(size) + ", not a power of two; using " + std::to_string(s.mapSize));
  return s;
}

}  // namespace ivshadow
