// SoTransparentShadowGroup renderer TRACER: the analytic pictures of the deep shadow tests,
// what GL drew before the group hiding what lies behind it, what GL draws after depth-testing
// against the traced picture, and what is traced or read again when something moves. Every
// picture is checked against an expectation computed without the tracer (ShadowScene's
// analytic picture, or a colour set in the scene).
#include "gl/GlCapabilities.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/CoinClock.h"
#include "tests/gl/ShadowScene.h"
#include "tests/gl/TracedRendering.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTranslation.h>
#include <Inventor/sensors/SoNodeSensor.h>
#include <Inventor/sensors/SoSensorManager.h>
#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

class TracedGroupAnalytic : public ::testing::TestWithParam<AnalyticCase> {};

TEST_P(TracedGroupAnalytic, MatchesThePicture) {
  const ShadowScene scene = traced(GetParam().scene);
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  const std::string failure = compareWithExpectation(image, GetParam().picture(), kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

INSTANTIATE_TEST_SUITE_P(Cases, TracedGroupAnalytic, ::testing::ValuesIn(analyticCases()),
                         analyticCaseName);

TEST(TracedGroup, WhatGlDrewInFrontBeforeTheGroupHidesTheTracedSurfaces) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  scene.aboveGroup = blueSquare(0.75);  // above the floor and the glass, nearer the camera
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  const std::string failure = compareWithExpectation(image, squareOrFloor(scene, true), kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(TracedGroup, WhatGlDrewBehindBeforeTheGroupIsHiddenByIt) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  scene.aboveGroup = blueSquare(-0.5);  // below the floor
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  const std::string failure =
      compareWithExpectation(image, squareOrFloor(scene, false), kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(TracedGroup, WhatGlDrawsAfterTheGroupDepthTestsAgainstItsPicture) {
  for (const double z : {0.75, -0.5}) {
    ShadowScene scene = traced(ShadowScene{});
    scene.filters = {kRedGlass, kGreenGlass};
    scene.belowGroup = blueSquare(z);
    const Image image = renderIv(scene.text(), ShadowScene::kSize);
    const std::string failure =
        compareWithExpectation(image, squareOrFloor(scene, z > 0.0), kTolerance);
    EXPECT_TRUE(failure.empty()) << "square at z = " << z << ": " << failure;
  }
}

TEST(TracedGroup, AStillFrameDrawsThePictureKeptAndAMoveTracesAgain) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  scene.floorNodes = "DEF Lift Translation { translation 0 0 0 }";
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  const SbVec3f place = r.lamp->location.getValue();
  r.lamp->location = SbVec3f(0.35f, -0.2f, 1.3f);
  DeepShadowStatistics stats = r.frame();
  EXPECT_EQ(stats.tracerScenes, 1);
  EXPECT_EQ(stats.tracerFrames, 1);
  stats = r.frame();
  EXPECT_EQ(stats.tracerFrames, 1) << "a still frame traces nothing";

  EXPECT_EQ(stats.tracerCameraRays, std::uint64_t(ShadowScene::kSize * ShadowScene::kSize));

  // A moved light: the lights alone are read again. The first picture kept no surfaces (a
  // single frame would only pay for them): the first change traces the camera rays again and
  // keeps what they meet; the next is traced from those.
  r.lamp->location = SbVec3f(0.3f, -0.1f, 1.2f);
  stats = r.frame();
  EXPECT_EQ(stats.tracerFrames, 2);
  EXPECT_EQ(stats.tracerCameraRays, std::uint64_t(ShadowScene::kSize * ShadowScene::kSize));
  r.lamp->location = place;
  r.expectAnalytic(scene, "after the light moved");
  stats = collectDeepShadowStatistics(r.root);
  EXPECT_EQ(stats.tracerScenes, 1);
  EXPECT_EQ(stats.tracerFrames, 3);
  EXPECT_EQ(stats.tracerCameraRays, 0u) << "the camera rays were traced again";

  // A moved camera, and back.
  auto* camera = static_cast<SoCamera*>(SoNode::getByName("Camera"));
  if (camera == nullptr) {
    SoSearchAction search;
    search.setType(SoCamera::getClassTypeId());
    search.apply(r.root);
    camera = static_cast<SoCamera*>(search.getPath()->getTail());
  }
  const SbVec3f eye = camera->position.getValue();
  camera->position = eye + SbVec3f(0.3f, 0.1f, 0.0f);
  stats = r.frame();
  EXPECT_EQ(stats.tracerFrames, 4);
  EXPECT_EQ(stats.tracerCameraRays, std::uint64_t(ShadowScene::kSize * ShadowScene::kSize));
  camera->position = eye;
  r.expectAnalytic(scene, "after the camera moved and came back");
  EXPECT_EQ(collectDeepShadowStatistics(r.root).tracerScenes, 1) << "the shapes were kept";

  // A moved caster (the floor): the subgraph is read again.
  auto* lift = static_cast<SoTranslation*>(SoNode::getByName("Lift"));
  ASSERT_NE(lift, nullptr);
  lift->translation = SbVec3f(0.0f, 0.0f, 0.1f);
  r.frame();
  lift->translation = SbVec3f(0.0f, 0.0f, 0.0f);
  r.expectAnalytic(scene, "after the floor moved and came back");
  EXPECT_EQ(collectDeepShadowStatistics(r.root).tracerScenes, 3);
}

// After a light moved the picture is composited from the surfaces kept, with their depth:
// GL drawing behind the floor after the group stays hidden.
TEST(TracedGroup, ThePictureOfAMovedLightKeepsItsDepth) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  scene.belowGroup = blueSquare(-0.5);
  Rendering r(scene);
  ASSERT_TRUE(r.renderer && r.lamp);
  const SbVec3f place = r.lamp->location.getValue();
  r.lamp->location = SbVec3f(0.35f, -0.2f, 1.3f);
  r.frame();
  // The first change keeps the surfaces (the first picture keeps none), the second reuses them.
  r.lamp->location = SbVec3f(0.3f, -0.1f, 1.2f);
  r.frame();
  r.lamp->location = place;
  ASSERT_EQ(r.frame().tracerCameraRays, 0u);
  const std::string failure =
      compareWithExpectation(r.renderer->read(), squareOrFloor(scene, false), kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// A moved camera re-reads only the lights: the picture is the one a fresh read of the scene
// with the camera there gives (the lights stay where they are in the world).
TEST(TracedGroup, AMovedCameraSeesWhatAFreshReadSees) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  const SbVec3f moved(0.3f, 0.1f, 5.0f);
  Rendering moving(scene);
  ASSERT_TRUE(moving.renderer);
  moving.frame();
  static_cast<SoCamera*>(moving.root->getChild(0))->position = moved;
  ASSERT_EQ(moving.frame().tracerScenes, 1) << "the shapes were read again";
  const Image afterMove = moving.renderer->read();
  Rendering fresh(scene);
  static_cast<SoCamera*>(fresh.root->getChild(0))->position = moved;
  fresh.frame();
  const Image expected = fresh.renderer->read();
  // Both are the same code's picture of the same view: equal but for float rounding.
  const std::string failure = compareWithExpectation(
      afterMove,
      [&expected](int x, int y) {
        const std::uint8_t* p = expected.pixel(x, y);
        return Expectation{true, {double(p[0]), double(p[1]), double(p[2])}};
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// A camera inside the group views its children, as GL draws them with it: the picture is
// the analytic one of that camera, whatever the camera above does; moving the inner camera
// traces again.
TEST(TracedGroup, ACameraInsideTheGroupIsTheOneTraced) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass, kGreenGlass};
  Rendering r(scene);
  ASSERT_TRUE(r.renderer);
  auto* outer = static_cast<SoOrthographicCamera*>(r.root->getChild(0));
  auto* group = static_cast<SoSeparator*>(SoNode::getByName("Group"));
  ASSERT_TRUE(outer->isOfType(SoOrthographicCamera::getClassTypeId()) && group != nullptr);
  auto* inner = static_cast<SoOrthographicCamera*>(outer->copy());
  group->insertChild(inner, 0);
  // The outer camera looks elsewhere: were it the one traced, the floor would be shifted.
  outer->position = SbVec3f(0.4f, 0.3f, 5.0f);
  r.expectAnalytic(scene, "the inner camera as the scene's");
  // The outer camera moves on: only the lights are read again, and the inner camera's
  // picture stays.
  outer->position = SbVec3f(-0.3f, 0.2f, 5.0f);
  r.expectAnalytic(scene, "after the outer camera moved");
  inner->position = SbVec3f(0.2f, 0.0f, 5.0f);
  r.frame();
  inner->position = SbVec3f(0.0f, 0.0f, 5.0f);
  r.expectAnalytic(scene, "after the inner camera moved and came back");
}

// A light above a group that has a camera of its own stays where GL put it, in the outer
// camera's eye space, which the inner camera views (GL does not move a light it was given):
// the traced picture is the GL path's (RAYS, exact shadows; the outside light only lights).
TEST(TracedGroup, ALightAboveAGroupWithItsOwnCameraStaysInPlace) {
  std::vector<Image> pictures;
  for (const char* renderer : {"TRACER", "RASTER"}) {
    ShadowScene scene{};
    scene.method = "RAYS";
    scene.renderer = renderer;
    scene.filters = {kRedGlass};
    scene.aboveGroup = "PointLight { location 0.6 0.4 0.8 intensity 0.6 }";
    Rendering r(scene);
    ASSERT_TRUE(r.renderer);
    auto* outer = static_cast<SoCamera*>(r.root->getChild(0));
    auto* group = static_cast<SoSeparator*>(SoNode::getByName("Group"));
    group->insertChild(outer->copy(), 0);
    outer->position = SbVec3f(0.4f, 0.3f, 5.0f);
    r.frame();
    pictures.push_back(r.renderer->read());
  }
  // The GL path lights per pixel in floats too, and rounds differently; its RAYS shadow edges
  // fall a pixel either way: 3 steps over 99 % of the pixels.
  int off = 0;
  for (int y = 0; y < ShadowScene::kSize; ++y)
    for (int x = 0; x < ShadowScene::kSize; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(pictures[0].pixel(x, y)[c]) - int(pictures[1].pixel(x, y)[c])) > 3) {
          ++off;
          break;
        }
  EXPECT_LT(off, ShadowScene::kSize * ShadowScene::kSize / 100) << "pixels apart by over 3 steps";
}

// The group is not notified of changes above it: a transform, a light or a material there
// changes what is traced all the same. Each case starts away from ShadowScene's picture and
// is put back; a picture kept from before would be the first frame's.
TEST(TracedGroup, ChangesAboveTheGroupAreTraced) {
  struct Case {
    const char* name;
    std::string above;
    std::function<void()> putBack;
  };
  const std::vector<Case> cases = {
      {"a translation", "DEF Shift Translation { translation 0.3 0 0 }",
       [] {
         static_cast<SoTranslation*>(SoNode::getByName("Shift"))->translation =
             SbVec3f(0.0f, 0.0f, 0.0f);
       }},
      {"a light", "DEF Above DirectionalLight { direction 0 0 -1 }",
       [] { static_cast<SoLight*>(SoNode::getByName("Above"))->on = FALSE; }},
      {"a material", "DEF Glow Material { emissiveColor 0.3 0.3 0.3 }",
       [] {
         static_cast<SoMaterial*>(SoNode::getByName("Glow"))->emissiveColor =
             SbColor(0.0f, 0.0f, 0.0f);
       }},
  };
  for (const Case& c : cases) {
    ShadowScene scene = traced(ShadowScene{});
    scene.filters = {kRedGlass};
    scene.aboveGroup = c.above;
    Rendering r(scene);
    ASSERT_TRUE(r.renderer);
    r.frame();
    c.putBack();
    r.expectAnalytic(scene, c.name);
  }
}

// Lines have no triangles to trace: GL draws them after the picture, depth-tested against
// it. A blue line over the floor is drawn; one under it is hidden by the traced floor.
TEST(TracedGroup, LinesAreDrawnThroughGlAgainstThePicturesDepth) {
  ShadowScene scene = traced(ShadowScene{});
  scene.filters = {kRedGlass};
  const std::string line =
      "LightModel { model BASE_COLOR } BaseColor { rgb 0 0 1 } DrawStyle { lineWidth 3 } ";
  scene.groupNodes = "DEF Outline Separator { " + line +
                     "Coordinate3 { point [ -0.9 -0.9 0.1, 0.9 0.9 0.1 ] } "
                     "DEF Seen LineSet { numVertices 2 } } "
                     "DEF Hidden Separator { " +
                     line +
                     "Coordinate3 { point [ -0.9 0.9 -0.5, 0.9 -0.9 -0.5 ] } "
                     "DEF Unseen LineSet { numVertices 2 } }";
  Rendering r(scene, true);
  ASSERT_TRUE(r.renderer);
  r.frame();
  r.frame();  // a still frame draws the lines again over the picture kept
  EXPECT_EQ(r.messagesWith({"renderer TRACER", "LineSet", "through GL"}), 2)
      << "each line named once";
  // On the visible line's centre (x = y, 0.1 above the floor, which the camera looks straight
  // down on: pixel (px, 239 - px)) blue; elsewhere the analytic floor, the hidden line's
  // diagonal included.
  const ShadowPicture floor{&scene, ColourModel::Saturate};
  const std::string failure = compareWithExpectation(
      r.renderer->read(),
      [&floor](int px, int py) {
        const int off = std::abs(px - (ShadowScene::kSize - 1 - py));
        const double x = -1.2 + (px + 0.5) / 100.0;
        if (off == 0 && std::fabs(x) < 0.8) return Expectation{true, {0.0, 0.0, 255.0}};
        return off > 4 ? floor(px, py) : Expectation{};
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(collectDeepShadowStatistics(r.root).tracerFrames, 1) << "the still frame traced";
}

// renderer AUTO, the default, traces on a software rasteriser (these machines: llvmpipe) and
// rasterises on a GPU, and says which once.
TEST(TracedGroup, AutoTracesOnASoftwareRasteriserAndSaysSo) {
  ShadowScene scene = ShadowScene{};
  scene.renderer = "";  // the group's default
  scene.filters = {kRedGlass};
  Rendering r(scene, true);
  ASSERT_TRUE(r.renderer);
  r.frame();
  r.expectAnalytic(scene, "renderer AUTO");
  const bool software = GlCapabilities::queryCurrent().isSoftwareRenderer();
  EXPECT_EQ(
      r.messagesWith({software ? "renderer AUTO uses TRACER on" : "renderer AUTO uses RASTER on"}),
      1);
  EXPECT_EQ(collectDeepShadowStatistics(r.root).tracerFrames, software ? 1 : 0);
  // What a host reads to show the choice (FreeCAD's add-on, through its C entry point).
  EXPECT_STREQ(ivshadow_renderer_in_use(r.root), software ? "TRACER" : "RASTER");
}

// The renderer in use is the one that drew the last frame: none before it, each group's own,
// MIXED where groups differ.
TEST(TracedGroup, TheRendererInUseIsTheOneThatDrewTheLastFrame) {
  for (const std::string renderer : {"TRACER", "RASTER"}) {
    ShadowScene scene = ShadowScene{};
    scene.renderer = renderer;
    scene.filters = {kRedGlass};
    Rendering r(scene, true);
    ASSERT_TRUE(r.renderer);
    EXPECT_STREQ(ivshadow_renderer_in_use(r.root), "") << renderer << ": before the first frame";
    r.frame();
    EXPECT_STREQ(ivshadow_renderer_in_use(r.root), renderer.c_str());
    EXPECT_EQ(collectDeepShadowStatistics(r.root).renderer, renderer);
    EXPECT_EQ(collectDeepShadowStatistics(r.root).tracerFrames, renderer == "TRACER" ? 1 : 0);
  }
  SoSeparator* root = readIv(R"(#Inventor V2.1 ascii
    OrthographicCamera { position 0 0 5 height 4 }
    TransparentShadowGroup { renderer TRACER DirectionalLight { } Cube { } }
    TransparentShadowGroup { renderer RASTER DirectionalLight { } Sphere { } })");
  std::string error;
  auto renderer = CheckedRenderer::create(64, 64, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  EXPECT_STREQ(ivshadow_renderer_in_use(root), "MIXED");
  EXPECT_STREQ(ivshadow_renderer_in_use(nullptr), "");
  renderer.reset();
  root->unref();
}

// A traced blue square (x, y in -0.5 .. 0.5, z 0.5) and an untraced yellow line (y = 0 from
// x = -1 to 1, z 0), unlit, seen 2.4 units high; `before` is drawn by GL before the group; a
// callback first in the root clears the depth buffer in every pass, as FreeCAD's saveImage
// does after its background.
SoSeparator* squareAndLineAfterADepthClear(const std::string& before) {
  SoSeparator* root = readIv(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
      "  LightModel { model BASE_COLOR }\n" +
      before +
      "  TransparentShadowGroup { renderer TRACER\n"
      "    BaseColor { rgb 0 0 1 }\n"
      "    Coordinate3 { point [ -0.5 -0.5 0.5, 0.5 -0.5 0.5, 0.5 0.5 0.5, -0.5 0.5 0.5 ] }\n"
      "    FaceSet { numVertices 4 }\n"
      "    BaseColor { rgb 1 1 0 }\n"
      "    Coordinate3 { point [ -1 0 0, 1 0 0 ] }\n"
      "    LineSet { numVertices 2 }\n"
      "  }\n}\n");
  auto* clear = new SoCallback;
  clear->setCallback(
      [](void*, SoAction* action) {
        if (action->isOfType(SoGLRenderAction::getClassTypeId())) glClear(GL_DEPTH_BUFFER_BIT);
      },
      nullptr);
  root->insertChild(clear, 0);
  return root;
}

// The shapes the tracer leaves to GL are drawn by a second render action, which traverses the
// state nodes above the group again: an application's callback there that clears the depth
// buffer (FreeCAD's saveImage clears it after its background) must not let a line behind the
// traced square show through it.
TEST(TracedGroup, ALineBehindATracedSurfaceStaysHiddenWhenACallbackAboveClearsTheDepth) {
  SoSeparator* root = squareAndLineAfterADepthClear("");
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  const Image image = renderer->read();
  root->unref();
  // 100 pixels per unit: the line crosses the middle row; the square covers x in -0.5 .. 0.5.
  const int middle = ShadowScene::kSize / 2;
  for (int x : {middle - 30, middle, middle + 30}) {
    const std::uint8_t* behind = image.pixel(x, middle);
    EXPECT_EQ(int(behind[0]), 0) << "the line shows through the square at x = " << x;
    EXPECT_EQ(int(behind[2]), 255) << "x = " << x;
  }
  // Beside the square the line is drawn.
  EXPECT_EQ(int(image.pixel(middle + 80, middle)[0]), 255) << "no line beside the square";
}

// The untraced shapes lie outside the box of the traced triangles: the depth written again
// before them (a callback above cleared it in their pass) is the whole viewport's, so a quad GL
// drew before the group, in front of the line and beside the square, still hides the line.
TEST(TracedGroup, AnUntracedLineBesideTheTrianglesStaysBehindWhatGlDrewBefore) {
  SoSeparator* root = squareAndLineAfterADepthClear(
      "  Separator { BaseColor { rgb 1 0 0 }\n"
      "    Coordinate3 { point [ 0.6 -0.2 0.8, 1 -0.2 0.8, 1 0.2 0.8, 0.6 0.2 0.8 ] }\n"
      "    FaceSet { numVertices 4 } }\n");
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  for (int frame = 0; frame < 3; ++frame) {
    renderer->render(root);
    const Image image = renderer->read();
    // 100 pixels per unit: the red quad covers x 0.6 .. 1 (pixels 180 .. 220) in front of the
    // line; the line shows at x = 0.55, between the square and the quad.
    const int middle = ShadowScene::kSize / 2;
    const std::uint8_t* front = image.pixel(middle + 80, middle);
    EXPECT_EQ(int(front[1]), 0) << "the line shows through the quad, frame " << frame;
    EXPECT_EQ(int(front[0]), 255) << "frame " << frame;
    EXPECT_EQ(int(image.pixel(middle + 55, middle)[1]), 255) << "no line, frame " << frame;
  }
  root->unref();
}

// A light moved twice: the second trace is reduced (movingResolution) and stretched over a
// wider box than the picture before it, so it must be traced at the depth GL holds now there,
// not the one read for an earlier frame: a pixel a callback had brought to the front before,
// and no longer does, is not given that depth back.
TEST(TracedGroup, AReducedTraceAfterAMovedLightTakesTheDepthGlHoldsNow) {
  SoSeparator* root = readIv(R"(#Inventor V2.1 ascii
    OrthographicCamera { position 0 0 5 height 4 nearDistance 1 farDistance 9 }
    TransparentShadowGroup {
      renderer TRACER
      movingResolution 0.5
      DEF Sun DirectionalLight { direction -0.3 -0.5 -1 }
      Sphere { radius 1.9 }
    })");
  // The sphere's box covers pixels 92 .. 548 across (120 a unit at 640 x 480, the centre at
  // 320); the region of a full picture reaches 4 pixels beyond, of a reduced one 6: pixels 86
  // and 87 lie between. Rows 239 .. 241 hold a reduced pixel's sample whatever its phase.
  constexpr int kWidth = 640, kHeight = 480, kX = 86, kY = 239;
  static bool poke = true;
  auto* near = new SoCallback;
  near->setCallback(
      [](void*, SoAction* action) {
        if (!poke || !action->isOfType(SoGLRenderAction::getClassTypeId())) return;
        glPushAttrib(GL_SCISSOR_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(kX, kY, 2, 3);
        glClearDepth(0.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        glPopAttrib();
      },
      nullptr);
  root->insertChild(near, 0);
  std::string error;
  auto renderer = CheckedRenderer::create(kWidth, kHeight, error);
  ASSERT_TRUE(renderer) << error;
  const auto depthAt = [&] {
    renderer->read();  // binds its framebuffer for reading
    float depth[6] = {-1.0f, -1.0f, -1.0f, -1.0f, -1.0f, -1.0f};
    glReadPixels(kX, kY, 2, 3, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    return *std::min_element(std::begin(depth), std::end(depth));
  };
  renderer->render(root);
  renderer->render(root);
  EXPECT_EQ(depthAt(), 0.0f) << "the callback's depth";
  poke = false;
  renderer->render(root);
  EXPECT_EQ(depthAt(), 1.0f) << "cleared, as GL drew it";
  auto* sun = static_cast<SoDirectionalLight*>(SoNode::getByName("Sun"));
  ASSERT_NE(sun, nullptr);
  const DeepShadowStatistics before = collectDeepShadowStatistics(root);
  sun->direction.setValue(0.3f, -0.5f, -1.0f);
  renderer->render(root);
  EXPECT_EQ(depthAt(), 1.0f) << "a full trace after the light moved";
  sun->direction.setValue(0.0f, -0.5f, -1.0f);
  renderer->render(root);
  const DeepShadowStatistics after = collectDeepShadowStatistics(root);
  EXPECT_EQ(after.tracerFrames, before.tracerFrames + 2);
  EXPECT_EQ(after.tracerReduced, 1) << "the second trace is reduced";
  EXPECT_EQ(depthAt(), 1.0f) << "the reduced trace after it";
  poke = true;
  root->unref();
}

// A setting that cannot act says so, once per light and field, and only the ones the user set:
// a traced group reads no light's method or map field; GL's path reads a map's fields for a
// map alone (RAYS reads none, MAP no opacity map's slices), and movingResolution only traces.
TEST(TracedGroup, FieldsThatCannotActSaySoOncePerLightAndField) {
  const auto said = [](const Rendering& r, const std::string& field, const std::string& why) {
    return r.messagesWith({"DeepShadowLight 'Lamp': " + field + " does nothing", why});
  };
  {
    ShadowScene scene = traced(ShadowScene{});
    scene.lightFields = "resolution 256 maxLayers 2";
    Rendering r(scene, true);
    r.frame();
    r.lamp->location = SbVec3f(0.1f, 0.0f, 1.0f);
    r.frame();
    for (const char* field : {"method", "resolution", "maxLayers"})
      EXPECT_EQ(said(r, field, "'Group' traces its children (renderer TRACER)"), 1) << field;
    EXPECT_EQ(r.messagesWith({"does nothing"}), 3) << "fields left at their defaults are quiet";
  }
  {
    ShadowScene scene{};  // RASTER
    scene.method = "RAYS";
    scene.lightFields = "resolution 256 filter NONE";
    scene.groupFields = "movingResolution 0.25";
    Rendering r(scene, true);
    r.frame();
    r.frame();
    EXPECT_EQ(said(r, "resolution", "the light traces shadow rays (RAYS)"), 1);
    EXPECT_EQ(said(r, "filter", "the light traces shadow rays (RAYS)"), 1);
    EXPECT_EQ(r.messagesWith({"'Group': movingResolution does nothing", "GL draws the children"}),
              1);
    EXPECT_EQ(r.messagesWith({"does nothing"}), 3);
  }
  {
    ShadowScene scene{};
    scene.lightFields = "resolution 256 maxLayers 2 slices 8";  // method MAP
    Rendering r(scene, true);
    r.frame();
    EXPECT_EQ(said(r, "slices", "the light builds a deep shadow map (MAP)"), 1);
    EXPECT_EQ(r.messagesWith({"does nothing"}), 1) << "a map reads resolution and maxLayers";
  }
}

// A peeling separator's passes do nothing where it does not peel by passes of its own: traced
// (its default here), or inside a peeling shadow group, which peels its children with the
// rest; its method does nothing in the group either. Said once per field the user set.
TEST(TracedGroup, APeelingSeparatorsFieldsThatCannotActSaySo) {
  const auto messages = [](const std::string& separator) {
    SoSeparator* root = readIv(
        "#Inventor V2.1 ascii\nSeparator {\n"
        "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n" +
        separator +
        "\n    Material { diffuseColor 1 0 0 transparency 0.5 }\n    Cube { }\n  }\n  }\n}\n");
    CoinMessageCapture capture;
    std::string error;
    auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
    EXPECT_TRUE(renderer) << error;
    if (renderer) {
      renderer->render(root);
      renderer->render(root);
    }
    root->unref();
    std::string said;
    for (const CoinMessageCapture::Message& message : capture.messages())
      if (message.text.find("does nothing") != std::string::npos) said += message.text + "\n";
    return said;
  };
  const std::string traced =
      messages("Separator { DEF Glass PeelingSeparator { maxPasses 8 earlyTermination FALSE");
  EXPECT_EQ(test::lines(traced).size(), 2u) << traced;
  EXPECT_NE(traced.find("'Glass': maxPasses does nothing: it traces its children"),
            std::string::npos)
      << traced;
  const std::string grouped = messages(
      "TransparentShadowGroup { renderer RASTER DirectionalLight { direction 0 0 -1 }\n"
      "  DEF Glass PeelingSeparator { method DUAL maxPasses 8");
  EXPECT_EQ(test::lines(grouped).size(), 2u) << grouped;
  EXPECT_NE(grouped.find("'Glass': method does nothing: the peeling above peels"),
            std::string::npos)
      << grouped;
  EXPECT_NE(grouped.find("'Glass': maxPasses does nothing: the peeling above peels"),
            std::string::npos)
      << grouped;
}

}  // namespace
}  // namespace ivshadow::test
