#pragma once

#include "headless/OffscreenRenderer.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace ivshadow::test {

// Fixture of the GL-layer tests (the FooGLTest files): a current GL context of its own, with
// KHR_debug reporting every GL error as it happens. A test that leaves a GL error behind, or
// made a call GL reported as an error, fails in TearDown, even when its own checks passed.
class GlContextTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Fails the current test (once) when GL reported errors since the last check, by KHR_debug
  // or left for glGetError, naming each, and forgets them.
  static void expectNoGlErrors();

  OffscreenRenderer& renderer() { return *renderer_; }

 private:
  std::unique_ptr<OffscreenRenderer> renderer_;
};

}  // namespace ivshadow::test
