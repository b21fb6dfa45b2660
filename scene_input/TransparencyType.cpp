#include "scene_input/TransparencyType.h"

#include "scene/InputError.h"

#include <utility>

namespace ivshadow {
namespace {

using Type = SoGLRenderAction::TransparencyType;

const std::pair<const char*, Type> kNames[] = {
    {"SCREEN_DOOR", SoGLRenderAction::SCREEN_DOOR},
    {"ADD", SoGLRenderAction::ADD},
    {"DELAYED_ADD", SoGLRenderAction::DELAYED_ADD},
    {"SORTED_OBJECT_ADD", SoGLRenderAction::SORTED_OBJECT_ADD},
    {"BLEND", SoGLRenderAction::BLEND},
    {"DELAYED_BLEND", SoGLRenderAction::DELAYED_BLEND},
    {"SORTED_OBJECT_BLEND", SoGLRenderAction::SORTED_OBJECT_BLEND},
    {"SORTED_OBJECT_SORTED_TRIANGLE_ADD", SoGLRenderAction::SORTED_OBJECT_SORTED_TRIANGLE_ADD},
    {"SORTED_OBJECT_SORTED_TRIANGLE_BLEND", SoGLRenderAction::SORTED_OBJECT_SORTED_TRIANGLE_BLEND},
    {"NONE", SoGLRenderAction::NONE},
    {"SORTED_LAYERS_BLEND", SoGLRenderAction::SORTED_LAYERS_BLEND},
};

}  // namespace

Type transparencyTypeFromName(const std::string& name) {
  std::string valid;
  for (const auto& [text, type] : kNames) {
    if (name == text) return type;
    valid += (valid.empty() ? "" : ", ") + std::string(text);
  }
  throw InputError("--transparency '" + name + "': error: expected one of " + valid);
}

std::string transparencyTypeName(Type type) {
  for (const auto& [text, value] : kNames) {
    if (value == type) return text;
  }
  return "UNKNOWN(" + std::to_string(static_cast<int>(type)) + ")";
}

}  // namespace ivshadow
