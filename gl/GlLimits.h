#pragma once

#include "gl/ShaderConstants.h"

namespace ivshadow {

// GL's integer state `name` (glGetIntegerv) in the current context.
int glInteger(unsigned int name);

}  // namespace ivshadow
