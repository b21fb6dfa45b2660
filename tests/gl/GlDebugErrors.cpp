#include "tests/gl/GlDebugErrors.h"

#include "gl/GlAllocationCheck.h"

#include <epoxy/gl.h>

namespace ivshadow::test {

GlDebugErrors::GlDebugErrors() {
  while (glGetError() != GL_NO_ERROR) {
  }
  // KHR_debug is core from OpenGL 4.3; the contexts here are 4.5, but a driver may say less.
  debugOutput_ = epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug");
  if (!debugOutput_) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  // report's parameters are GLDEBUGPROC's, spelt without GL's names in the header.
  glDebugMessageCallback(&GlDebugErrors::report, this);
  // Only errors: performance and portability remarks say nothing about correctness.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void GlDebugErrors::report(unsigned int, unsigned int type, unsigned int, unsigned int, int,
                           const char* message, const void* collector) {
  if (type != GL_DEBUG_TYPE_ERROR) return;
  auto* self = static_cast<GlDebugErrors*>(const_cast<void*>(collector));
  const std::lock_guard<std::mutex> lock(self->mutex_);
  self->reported_.emplace_back(message);
}

std::string GlDebugErrors::take(bool contextCurrent) {
  std::string errors;
  bool reported = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const std::string& message : reported_) errors += "\n  KHR_debug: " + message;
    reported_.clear();
    reportedUndrained_ = reportedUndrained_ || !errors.empty();
    if (contextCurrent) {
      reported = reportedUndrained_;
      reportedUndrained_ = false;
    }
  }
  if (!contextCurrent) return errors;
  // Every error KHR_debug reported is also kept for glGetError: the codes found after a report
  // repeat it. Without one they are errors it did not report (debug output was off).
  std::string kept;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
    kept += "\n  glGetError: " + glErrorName(error);
  return reported ? errors : errors + kept;
}

void GlDebugErrors::stop() {
  if (!debugOutput_) return;
  glDebugMessageCallback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDisable(GL_DEBUG_OUTPUT);
  debugOutput_ = false;
}

}  // namespace ivshadow::test
