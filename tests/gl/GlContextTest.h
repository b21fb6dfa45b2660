#pragma once

#include "tests/gl/CheckedRenderer.h"

#include <gtest/gtest.h>

#include <memory>

namespace ivshadow::test {

// Fixture of the GL-layer tests (the FooGLTest files): a current GL context of its own, with
// KHR_debug reporting every GL error as it happens (CheckedRenderer). A test that leaves a GL
// error behind, or made a call GL reported as an error, fails in TearDown, even when its own
// checks passed; a frame it renders is checked as it ends.
class GlContextTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Fails the current test (once) when GL reported errors since the last check, by KHR_debug
  // or left for glGetError, naming each, and forgets them.
  static void expectNoGlErrors();

  CheckedRenderer& renderer() { return *renderer_; }

 private:
  // The fixture's renderer, for the static check (one GL-layer test at a time).
  static CheckedRenderer* current_;
  std::unique_ptr<CheckedRenderer> renderer_;
};

}  // namespace ivshadow::test
