#include "nodes/IdleFields.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/CastingLight.h"
#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoNode.h>

namespace ivshadow {
namespace {

constexpr unsigned bit(int method) {
  return 1u << unsigned(method);
}
constexpr unsigned kMaps = bit(SoDeepShadowLight::MAP) | bit(SoDeepShadowLight::OPACITY_MAP);

// The shadow fields that some method does not read, and the methods that read each (the map
// fields are MapMethod's and the map lookup's alone); shadowColor and colorModel act on every
// path, the method wherever GL draws the group.
struct FieldUse {
  const char* name;
  unsigned methods;
};
constexpr FieldUse kFieldUses[] = {
    {"resolution", kMaps},
    {"maxLayers", bit(SoDeepShadowLight::MAP)},
    {"layerOverflow", bit(SoDeepShadowLight::MAP)},
    {"slices", bit(SoDeepShadowLight::OPACITY_MAP)},
    {"bias", kMaps},
    {"precision", kMaps},
    {"filter", kMaps},
    {"filterSize", kMaps},
    {"nearRadius", kMaps},
    {"farRadius", kMaps},
};

// What the lights did this frame, as the verb phrase of a sentence whose subject is one light
// or several.
std::string methodNames(unsigned methods, bool several) {
  const char* s = several ? "" : "s";
  if (methods == bit(SoDeepShadowLight::RAYS))
    return std::string("trace") + s + " shadow rays (RAYS)";
  if (methods == bit(SoDeepShadowLight::VOLUMES))
    return std::string("draw") + s + " shadow volumes (VOLUMES)";
  if (methods == bit(SoDeepShadowLight::MAP))
    return std::string("build") + s + " a deep shadow map (MAP)";
  if (methods == bit(SoDeepShadowLight::OPACITY_MAP))
    return std::string("build") + s + " an opacity map (OPACITY_MAP)";
  return std::string("cast") + s + " by several methods";
}

}  // namespace

SoNode& IdleFields::owner(SoLight& light, SoTransparentShadowGroup& group) {
  // As castingSettings chooses: a deep shadow light's own fields, the group's for the others.
  if (isDeepShadowLight(light)) return light;
  return group;
}

void IdleFields::used(SoLight& light, SoTransparentShadowGroup& group, int method) {
  methods_[&owner(light, group)] |= bit(method);
}

void IdleFields::say() {
  for (const auto& [fields, methods] : methods_) {
    const bool group = fields->isOfType(SoTransparentShadowGroup::getClassTypeId());
    const std::string why =
        std::string(group ? "the lights that cast with the group's fields " : "the light ") +
        methodNames(methods, group) + ", which does not read it";
    for (const FieldUse& use : kFieldUses)
      if ((use.methods & methods) == 0) sayIfSet(*fields, use.name, why);
  }
  methods_.clear();
}

void IdleFields::traced(SoLight& light, SoTransparentShadowGroup& group, const std::string& why) {
  SoNode& fields = owner(light, group);
  sayIfSet(fields, "method", why);
  for (const FieldUse& use : kFieldUses) sayIfSet(fields, use.name, why);
}

void IdleFields::sayIfSet(SoNode& node, const char* field, const std::string& why) {
  const SoField* f = node.getField(field);
  if (f == nullptr || f->isDefault()) return;
  if (!firstWarning(&node, std::string("idle field: ") + field)) return;
  SoDebugError::postWarning(node.getTypeId().getName().getString(), "%s: %s does nothing: %s",
                            describeNode(&node).c_str(), field, why.c_str());
}

}  // namespace ivshadow
