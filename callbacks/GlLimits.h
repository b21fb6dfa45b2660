#pragma once

#include "callbacks/ShaderConstants.h"

namespace ivshadow {

// GL's integer state `name` (glGetIntegerv) in the current context.
int glInteger(unsigned int name);

// How a surface filters light in a deep shadow map; the shaders receive the values as
// IVSHADOW_COLOUR_* (shaderConstantDefines()).
enum class ShadowColourModel : int { Monochrome = 0, Saturate = 1, Power = 2 };

}  // namespace ivshadow
