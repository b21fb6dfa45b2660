#include "nodes/IdleFields.h"

#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/ShadowFieldTable.h"
#include "raytrace/CastingLight.h"
#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoNode.h>

namespace ivshadow {
namespace {

// The shadow fields that some method does not read (the table's readBy: the map fields are
// MapMethod's and the map lookup's alone); shadowColor and colorModel act on every path, the
// method wherever GL draws the group.
bool someMethodIgnores(const ShadowFieldSpec& field) {
  return field.readBy != kEveryMethod;
}

// What the lights did this frame, as the verb phrase of a sentence whose subject is one light
// or several.
std::string methodNames(unsigned methods, bool several) {
  const char* s = several ? "" : "s";
  if (methods == methodBit(ShadowMethod::Rays))
    return std::string("trace") + s + " shadow rays (RAYS)";
  if (methods == methodBit(ShadowMethod::Volumes))
    return std::string("draw") + s + " shadow volumes (VOLUMES)";
  if (methods == methodBit(ShadowMethod::Map))
    return std::string("build") + s + " a deep shadow map (MAP)";
  if (methods == methodBit(ShadowMethod::OpacityMap))
    return std::string("build") + s + " an opacity map (OPACITY_MAP)";
  return std::string("cast") + s + " by several methods";
}

}  // namespace

SoNode& IdleFields::owner(SoLight& light, SoTransparentShadowGroup& group) {
  // As castingSettings chooses: a deep shadow light's own fields, the group's for the others.
  if (isDeepShadowLight(light)) return light;
  return group;
}

void IdleFields::used(SoLight& light, SoTransparentShadowGroup& group, ShadowMethod method) {
  methods_[&owner(light, group)] |= methodBit(method);
}

void IdleFields::say() {
  for (const auto& [fields, methods] : methods_) {
    const bool group = fields->isOfType(SoTransparentShadowGroup::getClassTypeId());
    const std::string why =
        std::string(group ? "the lights that cast with the group's fields " : "the light ") +
        methodNames(methods, group) + ", which does not read it";
    for (const ShadowFieldSpec& field : kShadowFields)
      if ((field.readBy & methods) == 0) sayIfSet(*fields, field.name, why);
  }
  methods_.clear();
}

void IdleFields::traced(SoLight& light, SoTransparentShadowGroup& group, const std::string& why) {
  SoNode& fields = owner(light, group);
  sayIfSet(fields, "method", why);
  for (const ShadowFieldSpec& field : kShadowFields)
    if (someMethodIgnores(field)) sayIfSet(fields, field.name, why);
}

void IdleFields::sayIfSet(SoNode& node, const char* field, const std::string& why) {
  const SoField* f = node.getField(field);
  if (f == nullptr || f->isDefault()) return;
  if (!firstWarning(&node, std::string("idle field: ") + field)) return;
  SoDebugError::postWarning(node.getTypeId().getName().getString(), "%s: %s does nothing: %s",
                            describeNode(&node).c_str(), field, why.c_str());
}

}  // namespace ivshadow
