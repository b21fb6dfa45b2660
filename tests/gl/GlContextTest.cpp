#include "tests/gl/GlContextTest.h"

#include "ivshadow/IvShadowInit.h"

namespace ivshadow::test {

CheckedRenderer* GlContextTest::current_ = nullptr;

void GlContextTest::SetUp() {
  init();
  std::string error;
  renderer_ = CheckedRenderer::create(64, 64, error);
  ASSERT_TRUE(renderer_) << error;
  current_ = renderer_.get();
}

void GlContextTest::TearDown() {
  if (!renderer_) return;
  expectNoGlErrors();
  current_ = nullptr;
  renderer_.reset();
}

void GlContextTest::expectNoGlErrors() {
  current_->expectNoGlErrors("in the test");
}

}  // namespace ivshadow::test
