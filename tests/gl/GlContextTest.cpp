#include "tests/gl/GlContextTest.h"

#include "ivshadow/IvShadowInit.h"

#include <epoxy/gl.h>

#include <sstream>

namespace ivshadow::test {
namespace {

// Messages of type GL_DEBUG_TYPE_ERROR since the last check (the callback runs on the
// calling thread: output is synchronous).
std::vector<std::string>& reported() {
  static std::vector<std::string> messages;
  return messages;
}

void GLAPIENTRY collect(GLenum, GLenum type, GLuint, GLenum, GLsizei, const GLchar* message,
                        const void*) {
  if (type == GL_DEBUG_TYPE_ERROR) reported().emplace_back(message);
}

std::string errorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default: {
      std::ostringstream text;
      text << "GL error 0x" << std::hex << error;
      return text.str();
    }
  }
}

}  // namespace

void GlContextTest::SetUp() {
  init();
  std::string error;
  renderer_ = OffscreenRenderer::create(64, 64, error);
  ASSERT_TRUE(renderer_) << error;
  // What context creation left is not the test's doing.
  while (glGetError() != GL_NO_ERROR) {
  }
  reported().clear();
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(collect, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void GlContextTest::TearDown() {
  if (!renderer_) return;
  expectNoGlErrors();
  glDebugMessageCallback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDisable(GL_DEBUG_OUTPUT);
  renderer_.reset();
}

void GlContextTest::expectNoGlErrors() {
  std::string errors;
  for (const std::string& message : reported()) errors += "\n  KHR_debug: " + message;
  reported().clear();
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
    errors += "\n  glGetError: " + errorName(error);
  if (!errors.empty()) ADD_FAILURE() << "GL errors:" << errors;
}

}  // namespace ivshadow::test
