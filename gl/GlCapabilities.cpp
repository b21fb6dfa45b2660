#include "gl/GlCapabilities.h"

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
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &caps.maxRenderbufferSize);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &caps.maxTextureSize);
  GLint viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  caps.maxViewportWidth = viewport[0];
  caps.maxViewportHeight = viewport[1];
  return caps;
}

std::string GlCapabilities::sizeProblem(int width, int height) const {
  const std::string gl = " of this GL (" + renderer + ")";
  const auto side = [](int limit) { return std::to_string(limit) + " pixels per side"; };
  if (width > maxRenderbufferSize || height > maxRenderbufferSize)
    return "GL_MAX_RENDERBUFFER_SIZE" + gl + " is " + side(maxRenderbufferSize);
  if (width > maxTextureSize || height > maxTextureSize)
    return "GL_MAX_TEXTURE_SIZE" + gl + " is " + side(maxTextureSize);
  if (width > maxViewportWidth || height > maxViewportHeight)
    return "GL_MAX_VIEWPORT_DIMS" + gl + " is " + std::to_string(maxViewportWidth) + "x" +
           std::to_string(maxViewportHeight);
  return {};
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
