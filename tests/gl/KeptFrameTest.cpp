// A traced group's still frames (gl/KeptFrame): while nothing changes, the framebuffer
// the picture left is put back by one blit instead of compositing the picture again, and it is
// the composite's picture to the bit, colour and depth; a change of what GL drew before the
// group composites the picture again, without tracing it.
#include "gl/KeptFrame.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SbColor.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoSeparator.h>
#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <memory>
#include <optional>
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

// One pixel of what GL draws before the group, changed by a scissored clear: its colour, or
// its depth alone (colour writes off).
struct Poke {
  int x = 0;
  int y = 0;
  bool depthOnly = false;
  // Within the box around the group's triangles as the camera sees them (the pixels its
  // picture may change), worked out below from the scene.
  bool inside = true;
};

void pokePixel(void* data, SoAction* action) {
  const auto& poke = *static_cast<const std::optional<Poke>*>(data);
  if (!poke || !action->isOfType(SoGLRenderAction::getClassTypeId())) return;
  glPushAttrib(GL_SCISSOR_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(poke->x, poke->y, 1, 1);
  if (poke->depthOnly) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClearDepth(0.0);
    glClear(GL_DEPTH_BUFFER_BIT);
  } else {
    glClearColor(0.2f, 0.6f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glPopAttrib();
}

// A glass cube in front of an opaque sphere of radius 1.9, traced; a callback before the group
// pokes one pixel when asked. The camera shows 4 units across 480 rows, 120 pixels a unit, the
// origin at pixel (320, 240): the triangles' box spans pixels 92 .. 548 across and 12 .. 468
// up, and the region the picture may change is that, 4 pixels wider on each side (the margin
// of nodes/GroupTracer.cpp at full resolution).
SoSeparator* pokedScene(std::optional<Poke>* poke) {
  SoSeparator* scene = readIv(R"(#Inventor V2.1 ascii
    OrthographicCamera { position 0 0 5 height 4 nearDistance 1 farDistance 9 }
    TransparentShadowGroup {
      renderer TRACER
      DEF Sun DirectionalLight { direction -0.3 -0.5 -1 }
      Material { diffuseColor 0.8 0.8 0.8 }
      Sphere { radius 1.9 }
      Translation { translation 0.4 0.3 1 }
      Material { diffuseColor 0 0.4 1 transparency 0.5 }
      Cube { width 0.8 height 0.8 depth 0.8 }
    })");
  auto* root = new SoSeparator;
  root->ref();
  auto* callback = new SoCallback;
  callback->setCallback(pokePixel, poke);
  root->addChild(callback);
  root->addChild(scene);
  scene->unref();
  return root;
}

// 640 x 480: the region is several of KeptFrame's bands of 256 KiB (141 rows of its 464 pixels),
// so that a change in the first, a middle and the last band, and about a band's edge, is each
// seen.
constexpr int kPokeWidth = 640;
constexpr int kPokeHeight = 480;

// The first frame of the poked scene on a fresh renderer: the picture composited once over
// what GL drew, with nothing kept.
Image firstPokedFrame(const std::optional<Poke>& poke) {
  std::optional<Poke> fixed = poke;
  SoSeparator* root = pokedScene(&fixed);
  std::string error;
  auto renderer = CheckedRenderer::create(kPokeWidth, kPokeHeight, error);
  EXPECT_TRUE(renderer) << error;
  Image image;
  if (renderer) {
    renderer->render(root);
    image = renderer->read();
  }
  root->unref();
  return image;
}

TEST(KeptFrame, OnePixelChangedBeforeTheGroupWhereThePictureMayChangeCompositesAgain) {
  std::optional<Poke> poke;
  SoSeparator* root = pokedScene(&poke);
  std::string error;
  auto renderer = CheckedRenderer::create(kPokeWidth, kPokeHeight, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  renderer->render(root);  // keeps the frame
  const Image unpoked = renderer->read();
  const std::vector<float> unpokedDepth = depthOf(*renderer);
  const std::vector<Poke> pokes = {
      {320, 10, false},         {320, 470, false},       {300, 149, false},
      {300, 150, false},        {330, 250, false},       {90, 240, false},
      {320, 240, true},         {90, 240, true},         {0, 0, false, false},
      {639, 479, false, false}, {20, 240, false, false}, {600, 300, true, false},
  };
  GlCallCounter calls;
  for (const Poke& where : pokes) {
    const std::string name = "pixel " + std::to_string(where.x) + ", " + std::to_string(where.y) +
                             (where.depthOnly ? ", its depth" : ", its colour");
    poke = where;
    calls.reset();
    renderer->render(root);
    // Outside the region the picture leaves what GL drew, whatever it is: put back as kept.
    EXPECT_EQ(calls.draws(), where.inside ? 1 : 0) << name << ": composited again";
    const Image poked = renderer->read();
    EXPECT_TRUE(samePixels(poked, firstPokedFrame(poke))) << name;
    poke.reset();
    calls.reset();
    renderer->render(root);
    EXPECT_EQ(calls.draws(), where.inside ? 1 : 0) << name << " put back: composited again";
    // A changed depth is traced again, and the frame after that (this one) is part of a
    // motion, traced at movingResolution: the still frame after it is the full picture.
    if (!where.depthOnly) EXPECT_TRUE(samePixels(renderer->read(), unpoked)) << name << " put back";
    renderer->render(root);
    EXPECT_TRUE(samePixels(renderer->read(), unpoked)) << name << " put back, still";
    EXPECT_EQ(depthOf(*renderer), unpokedDepth) << name << " put back, still";
    // After a depth traced again that still frame refined the picture: the next one keeps it.
    renderer->render(root);
  }
  renderer->render(root);
  calls.reset();
  renderer->render(root);
  EXPECT_EQ(calls.draws(), 0) << "still";
  EXPECT_EQ(calls.blits(), 1) << "still";
  EXPECT_TRUE(samePixels(renderer->read(), unpoked)) << "still";

  // A depth changed outside the region is not traced again; a moved light then traces the
  // picture at the depth it was traced at before, and its composite must leave the depth GL
  // drew outside the region: the poke's, 0, not the cleared depth the picture holds there.
  poke = Poke{600, 300, true, false};
  renderer->render(root);
  auto* sun = static_cast<SoDirectionalLight*>(SoNode::getByName("Sun"));
  ASSERT_NE(sun, nullptr);
  sun->direction.setValue(0.3f, -0.5f, -1.0f);
  const int tracedBefore = collectDeepShadowStatistics(root).tracerFrames;
  renderer->render(root);
  EXPECT_EQ(collectDeepShadowStatistics(root).tracerFrames, tracedBefore + 1) << "traced";
  EXPECT_EQ(depthOf(*renderer)[std::size_t(300 * kPokeWidth + 600)], 0.0f);
  renderer.reset();
  root->unref();
}

// The depth kept as the one traced at belongs to the viewport it was read in: a later viewport
// whose whole equals the region read before, over a depth of the same bytes (a cleared
// buffer), is another picture's.
TEST(KeptFrame, TheDepthTracedAtBelongsToItsViewport) {
  init();  // Coin, before a renderer is made (the other tests read a scene first)
  std::string error;
  auto renderer = CheckedRenderer::create(64, 64, error);
  ASSERT_TRUE(renderer) << error;
  KeptFrame frame;
  renderer->render([&](SoGLRenderAction&) {
    glClear(GL_DEPTH_BUFFER_BIT);
    ASSERT_TRUE(frame.readBefore({0, 0, 64, 64}, {0, 0, 64, 64}));
    frame.markTraced({0, 0, 32, 32});
    ASSERT_TRUE(frame.readBefore({0, 0, 64, 64}, {0, 0, 32, 32}));
    EXPECT_TRUE(frame.depthAsTraced()) << "the same viewport, region and depth";
    ASSERT_TRUE(frame.readBefore({0, 0, 32, 32}, {0, 0, 32, 32}));
    EXPECT_FALSE(frame.depthAsTraced()) << "another viewport";
  });
}

}  // namespace
}  // namespace ivshadow::test
