#pragma once

#include <Inventor/actions/SoGLRenderAction.h>

#include <string>

namespace ivshadow {

// Coin's SoGLRenderAction::TransparencyType by its enum name ("SORTED_LAYERS_BLEND", ...).
// Throws InputError listing the valid names.
SoGLRenderAction::TransparencyType transparencyTypeFromName(const std::string& name);
std::string transparencyTypeName(SoGLRenderAction::TransparencyType type);

}  // namespace ivshadow
