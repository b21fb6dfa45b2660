#include "gl/GlCapabilities.h"
#include "image_files/PngFile.h"
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>

namespace ivshadow {
namespace {

std::string example(const std::string& name) {
  return std::string(IVSHADOW_BIN_DIR) + "/" + name;
}

// Binary PPM (P6, 8-bit) as written by examples/load_plugin_from_file.cpp.
Image readPpm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0, height = 0, maximum = 0;
  in >> magic >> width >> height >> maximum;
  in.get();
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      char rgb[3];
      in.read(rgb, 3);
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = static_cast<std::uint8_t>(rgb[c]);
      image.pixel(x, y)[3] = 255;
    }
  return image;
}

TEST(Examples, SceneGraphBuiltInCxxRendersWithShadowsAndPeeling) {
  const std::string out = test::outputDir() + "/scene_graph.png";
  const test::ProcessResult result = test::run({example("render_scene_graph"), out});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // The group's default renderer, AUTO: traced on a software rasteriser (every pixel of the
  // 640 x 480 picture), a map on a GPU; this process's EGL context is the example's.
  ivshadow::init();  // Coin first: the context asks it for a cache context
  std::string error;
  const auto context = test::CheckedRenderer::create(1, 1, error);
  ASSERT_TRUE(context) << error;
  const bool software = context->capabilities().isSoftwareRenderer();
  EXPECT_NE(result.out.find(software ? "traced on the CPU: 1 frame, 307200 camera rays"
                                     : "deep shadow map built 1 time, 1 light"),
            std::string::npos)
      << result.out;
  EXPECT_EQ(readPng(out).width(), 640);
}

TEST(Examples, ACoinOnlyProgramLoadsThePluginFromTheSceneFile) {
  const std::string dir = test::outputDir();
  const std::string scene = test::scenesDir() + "/coloured_shadows.iv";
  const test::ProcessResult loaded =
      test::run({example("load_plugin_from_file"), scene, dir + "/loaded.ppm", "320x240"},
                {std::string("LD_LIBRARY_PATH=") + IVSHADOW_LIBRARY_DIR});
  ASSERT_EQ(loaded.exitCode, 0) << loaded.err;
  const test::ProcessResult rendered = test::run(
      {test::ivshadowExe(), "render", scene, "-o", dir + "/rendered.png", "--size", "320x240"});
  ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
  // Same Coin, same plugin, same EGL rasteriser: the same picture, shadows and all.
  const Image a = readPpm(dir + "/loaded.ppm"), b = readPng(dir + "/rendered.png");
  ASSERT_EQ(a.width(), b.width());
  int different = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      for (int c = 0; c < 3; ++c) different += a.pixel(x, y)[c] != b.pixel(x, y)[c] ? 1 : 0;
  EXPECT_EQ(different, 0);
}

}  // namespace
}  // namespace ivshadow
