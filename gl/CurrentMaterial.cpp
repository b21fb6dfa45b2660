#include "gl/CurrentMaterial.h"

#include <epoxy/gl.h>

#include <cstring>

namespace ivshadow {

bool materialLagsBehindGlMaterial() {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return version != nullptr && std::strstr(version, "Mesa") != nullptr;
}

void flushBufferedVertices() {
  glFlush();
}

}  // namespace ivshadow
