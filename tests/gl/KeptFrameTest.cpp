// A traced group's still frames (gl/KeptFrame): while nothing changes, the framebuffer
// the picture left is put back by one blit instead of compositing the picture again, and it is
// the composite's picture to the bit, colour and depth; a change of what GL drew before the
// group composites the picture again, without tracing it.
#include "ivshadow/DeepShadowStatistics.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SbColor.h>
#include <Inventor/nodes/SoSeparator.h>
#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

// The tracer shades and composites in floats and the picture is blended once onto a black
// framebuffer, then rounded to 8 bits: one step (as tests/gl/GroupTracerTest.cpp).
constexpr double kTolerance = 1.0;

ShadowScene tracedGlass() {
  ShadowScene scene;
  scene.renderer = "TRACER";
  scene.filters = {kRedGlass, kGreenGlass};
  return scene;
}

// The renderer's framebuffer's depth, as GL converts it to floats.
std::vector<float> depthOf(CheckedRenderer& renderer) {
  renderer.read();  // binds its framebuffer for reading
  std::vector<float> depth(std::size_t(renderer.width()) * std::size_t(renderer.height()));
  glReadPixels(0, 0, renderer.width(), renderer.height(), GL_DEPTH_COMPONENT, GL_FLOAT,
               depth.data());
  return depth;
}

bool samePixels(const Image& a, const Image& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.data(), b.data(), std::size_t(a.width()) * std::size_t(a.height()) * 4) == 0;
}

// The scene's first frame on a fresh renderer with `background`: the picture composited once,
// with nothing kept.
Image firstFrame(const ShadowScene& scene, const SbColor& background) {
  SoSeparator* root = readIv(scene.text());
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  EXPECT_TRUE(renderer) << error;
  Image image;
  if (renderer) {
    renderer->setBackground(background);
    renderer->render(root);
    image = renderer->read();
  }
  root->unref();
  return image;
}

TEST(KeptFrame, AStillFrameIsPutBackByABlitAndIsTheCompositesPicture) {
  const ShadowScene scene = tracedGlass();
  SoSeparator* root = readIv(scene.text());
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  const Image first = renderer->read();
  const std::vector<float> firstDepth = depthOf(*renderer);
  EXPECT_EQ(collectDeepShadowStatistics(root).tracerFrames, 1);

  GlCallCounter calls;
  // The first still frame composites the picture (its one screen triangle) and keeps what
  // that leaves (a blit into the copy); the next ones only blit it back.
  renderer->render(root);
  EXPECT_EQ(calls.draws(), 1);
  EXPECT_EQ(calls.blits(), 1);
  for (int frame = 0; frame < 2; ++frame) {
    calls.reset();
    renderer->render(root);
    EXPECT_EQ(calls.draws(), 0) << "a still frame composites nothing";
    EXPECT_EQ(calls.blits(), 1);
    const Image still = renderer->read();
    EXPECT_TRUE(samePixels(still, first)) << "frame " << frame;
    EXPECT_EQ(depthOf(*renderer), firstDepth) << "frame " << frame;
    const std::string failure =
        compareWithExpectation(still, ShadowPicture{&scene, ColourModel::Saturate}, kTolerance);
    EXPECT_TRUE(failure.empty()) << failure;
  }

  // What GL drew before the group changes (the cleared colour): the picture is composited
  // again over it, not traced, and is what a first frame over that colour is.
  const SbColor white(1.0f, 1.0f, 1.0f);
  const Image overWhite = firstFrame(scene, white);
  ASSERT_FALSE(samePixels(overWhite, first)) << "the background shows somewhere";
  renderer->setBackground(white);
  for (int frame = 0; frame < 2; ++frame) {
    calls.reset();
    renderer->render(root);
    EXPECT_EQ(calls.draws(), frame == 0 ? 1 : 0) << "frame " << frame << " over white";
    EXPECT_TRUE(samePixels(renderer->read(), overWhite)) << "frame " << frame << " over white";
  }
  renderer->setBackground(SbColor(0.0f, 0.0f, 0.0f));
  renderer->render(root);
  EXPECT_TRUE(samePixels(renderer->read(), first)) << "black again";
  EXPECT_EQ(collectDeepShadowStatistics(root).tracerFrames, 1) << "nothing was traced again";
  renderer.reset();
  root->unref();
}

}  // namespace
}  // namespace ivshadow::test
