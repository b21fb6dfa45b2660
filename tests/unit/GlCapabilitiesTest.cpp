#include "gl/GlCapabilities.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

GlCapabilities limits(int renderbuffer, int texture, int viewportWidth, int viewportHeight) {
  GlCapabilities caps;
  caps.renderer = "test GL";
  caps.maxRenderbufferSize = renderbuffer;
  caps.maxTextureSize = texture;
  caps.maxViewportWidth = viewportWidth;
  caps.maxViewportHeight = viewportHeight;
  return caps;
}

TEST(GlCapabilities, SizesUpToEveryLimitFit) {
  const GlCapabilities caps = limits(8192, 4096, 4096, 2048);
  EXPECT_EQ(caps.sizeProblem(4096, 2048), "");
  EXPECT_EQ(caps.sizeProblem(1, 1), "");
}

TEST(GlCapabilities, TheFirstLimitExceededIsNamed) {
  EXPECT_EQ(limits(4096, 8192, 8192, 8192).sizeProblem(4097, 10),
            "GL_MAX_RENDERBUFFER_SIZE of this GL (test GL) is 4096 pixels per side");
  EXPECT_EQ(limits(8192, 4096, 8192, 8192).sizeProblem(10, 4097),
            "GL_MAX_TEXTURE_SIZE of this GL (test GL) is 4096 pixels per side");
  // The viewport limit has a width and a height of its own.
  EXPECT_EQ(limits(8192, 8192, 8192, 2048).sizeProblem(4096, 2049),
            "GL_MAX_VIEWPORT_DIMS of this GL (test GL) is 8192x2048");
}

}  // namespace
}  // namespace ivshadow
