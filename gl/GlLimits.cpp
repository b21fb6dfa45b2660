#include "gl/GlLimits.h"

#include <epoxy/gl.h>

namespace ivshadow {

int glInteger(unsigned int name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}

}  // namespace ivshadow
