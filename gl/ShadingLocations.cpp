#include "gl/ShadingLocations.h"

#include "gl/UniformLocations.h"

namespace ivshadow {
namespace {

bool identifierCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Whether `text` holds `name` as a whole word.
bool mentions(std::string_view text, std::string_view name) {
  for (std::size_t at = text.find(name); at != std::string_view::npos;
       at = text.find(name, at + 1)) {
    const std::size_t end = at + name.size();
    if ((at == 0 || !identifierCharacter(text[at - 1])) &&
        (end == text.size() || !identifierCharacter(text[end])))
      return true;
  }
  return false;
}

// Every name of the table, in its order.
std::vector<std::string_view> names() {
  return {
#define IVSHADOW_SHADING_NAME(name) #name,
      IVSHADOW_SHADING_UNIFORMS(IVSHADOW_SHADING_NAME)
#undef IVSHADOW_SHADING_NAME
#define IVSHADOW_LIGHT_SLOT_NAME(glslType, perSlot, Element, member, uniform, initial) #uniform,
          IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_LIGHT_SLOT_NAME)
#undef IVSHADOW_LIGHT_SLOT_NAME
  };
}

}  // namespace

ShadingLocations::ShadingLocations(const UniformLocations& locations)
    : program(locations.program()) {
#define IVSHADOW_FIND_SHADING_LOCATION(name) name = locations[#name];
  IVSHADOW_SHADING_UNIFORMS(IVSHADOW_FIND_SHADING_LOCATION)
#undef IVSHADOW_FIND_SHADING_LOCATION
#define IVSHADOW_FIND_LIGHT_SLOT_LOCATION(glslType, perSlot, Element, member, uniform, initial) \
  uniform = locations[#uniform];
  IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_FIND_LIGHT_SLOT_LOCATION)
#undef IVSHADOW_FIND_LIGHT_SLOT_LOCATION
}

std::vector<std::string_view> ShadingLocations::undeclared(std::string_view declarations) {
  std::vector<std::string_view> missing;
  for (std::string_view name : names())
    if (!mentions(declarations, name)) missing.push_back(name);
  return missing;
}

}  // namespace ivshadow
