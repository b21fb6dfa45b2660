// The GL test fixture itself: a GL error a test leaves behind fails that test.
#include "tests/gl/GlContextTest.h"

#include <epoxy/gl.h>

#include <gtest/gtest-spi.h>

namespace ivshadow::test {
namespace {

class GlContextGLTest : public GlContextTest {};

TEST_F(GlContextGLTest, AGlErrorFailsTheTest) {
  // 0x1234 names no capability: GL_INVALID_ENUM, reported by KHR_debug and kept for glGetError.
  glEnable(GLenum(0x1234));
  EXPECT_NONFATAL_FAILURE(expectNoGlErrors(), "glGetError: GL_INVALID_ENUM");
}

TEST_F(GlContextGLTest, KhrDebugReportsTheCallAsItHappens) {
  glEnable(GLenum(0x1234));
  EXPECT_NONFATAL_FAILURE(expectNoGlErrors(), "KHR_debug: ");
}

TEST_F(GlContextGLTest, AValidCallPasses) {
  glEnable(GL_BLEND);
  glDisable(GL_BLEND);
  expectNoGlErrors();
}

}  // namespace
}  // namespace ivshadow::test
