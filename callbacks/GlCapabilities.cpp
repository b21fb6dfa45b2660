#include "callbacks/GlCapabilities.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>

namespace ivshadow {
namespace {

std::string glString(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text ? std::string(text) : std::string();
}

}  // namespace

GlCapabilities GlCapabilities::queryCurrent() {
  GlCapabilities caps;
  caps.version = glString(GL_VERSION);
  caps.renderer = glString(GL_RENDERER);
  caps.vendor = glString(GL_VENDOR);
  caps.major = epoxy_gl_version() / 10;
  caps.minor = epoxy_gl_version() % 10;
  if (caps.major >= 3 && (caps.major > 3 || caps.minor >= 2)) {
    GLint mask = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    caps.compatibilityProfile = (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
  } else {
    caps.compatibilityProfile = true;
  }
  caps.framebufferObjects = caps.major >= 3 || epoxy_has_gl_extension("GL_ARB_framebuffer_object");
  caps.timerQueries = (caps.major > 3 || (caps.major == 3 && caps.minor >= 3)) ||
                      epoxy_has_gl_extension("GL_ARB_timer_query");
  return caps;
}

bool GlCapabilities::isSoftwareRenderer() const {
  std::string lower = renderer;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "software rasterizer"}) {
    if (lower.find(name) != std::string::npos) return true;
  }
  return false;
}

}  // namespace ivshadow
