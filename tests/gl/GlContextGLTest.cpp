// The GL test fixture and the tests' renderer and clock themselves: a GL error a test leaves
// behind, or a frame makes, fails that test; Coin's timers fire when the tests' clock says.
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/CoinClock.h"
#include "tests/gl/GlContextTest.h"

#include <Inventor/SoDB.h>
#include <Inventor/sensors/SoAlarmSensor.h>
#include <Inventor/sensors/SoSensorManager.h>

#include <epoxy/gl.h>

#include <gtest/gtest-spi.h>

namespace ivshadow::test {
namespace {

class GlContextGLTest : public GlContextTest {};

TEST_F(GlContextGLTest, KhrDebugReportsTheCallAsItHappens) {
  // 0x1234 names no capability: GL_INVALID_ENUM, reported by KHR_debug and kept for glGetError
  // (the kept code repeats the report and is not named again).
  glEnable(GLenum(0x1234));
  EXPECT_NONFATAL_FAILURE(expectNoGlErrors(), "KHR_debug: GL_INVALID_ENUM in glEnable(0x1234)");
  expectNoGlErrors();
}

TEST_F(GlContextGLTest, AnErrorKhrDebugDidNotReportIsFoundByGlGetError) {
  glDisable(GL_DEBUG_OUTPUT);
  glEnable(GLenum(0x1234));
  glEnable(GL_DEBUG_OUTPUT);
  EXPECT_NONFATAL_FAILURE(expectNoGlErrors(), "glGetError: GL_INVALID_ENUM");
}

TEST_F(GlContextGLTest, AValidCallPasses) {
  glEnable(GL_BLEND);
  glDisable(GL_BLEND);
  expectNoGlErrors();
}

// Every in-process render of the tests goes through CheckedRenderer: a GL error made while
// Coin traverses (here by a callback) fails the test that rendered.
TEST(CheckedRenderer, AGlErrorInAFrameFailsTheTest) {
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(8, 8, error);
  ASSERT_TRUE(renderer) << error;
  EXPECT_NONFATAL_FAILURE(renderer->render([](SoGLRenderAction&) { glEnable(GLenum(0x1234)); }),
                          "GL errors in the frame:\n  KHR_debug: ");
  renderer->render([](SoGLRenderAction&) {});  // nothing left over for the next frame
}

// A call the test made on the renderer's context between frames is told apart from them.
TEST(CheckedRenderer, AGlErrorBetweenFramesFailsTheTest) {
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(8, 8, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render([](SoGLRenderAction&) {});
  glEnable(GLenum(0x1234));
  EXPECT_NONFATAL_FAILURE(renderer->render([](SoGLRenderAction&) {}),
                          "GL errors since the last frame:");
}

// The GL tests' clock for Coin (CoinClock.h) is the one Coin's sensors read: an alarm a
// thousand seconds away fires once the clock is moved past it, and not before.
TEST(CoinClock, AnAlarmFiresOnceTheClockIsMovedPastIt) {
  init();
  bool fired = false;
  SoAlarmSensor alarm([](void* data, SoSensor*) { *static_cast<bool*>(data) = true; }, &fired);
  alarm.setTimeFromNow(SbTime(1000.0));
  alarm.schedule();
  SoDB::getSensorManager()->processTimerQueue();
  EXPECT_FALSE(fired);
  advanceCoinClock(1000.0);
  SoDB::getSensorManager()->processTimerQueue();
  EXPECT_TRUE(fired);
}

}  // namespace
}  // namespace ivshadow::test
