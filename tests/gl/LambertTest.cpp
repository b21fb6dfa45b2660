#include "ivshadow/IvShadowInit.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/LitPlane.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

TEST(HeadlessRendering, PointLitPlaneMatchesLambertEverywhere) {
  init();
  std::string error;
  auto renderer =
      test::CheckedRenderer::create(test::LitPlane::kSize, test::LitPlane::kSize, error);
  ASSERT_TRUE(renderer) << error;
  LoadedScene scene = loadScene(test::scenesDir() + "/lit_plane.iv");
  const ViewSetup view = ViewSetup::prepare(scene.root.get(), SbViewportRegion(240, 240));
  EXPECT_FALSE(view.addedCamera);
  EXPECT_FALSE(view.addedHeadlight);
  renderer->render(view.root.get());
  const std::string failure =
      test::compareWithExpectation(renderer->read(), test::LitPlane{}, test::kLitPlaneTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(HeadlessRendering, RepeatedFramesAreIdentical) {
  init();
  std::string error;
  auto renderer = test::CheckedRenderer::create(64, 48, error);
  ASSERT_TRUE(renderer) << error;
  LoadedScene scene = loadScene(test::scenesDir() + "/coloured_glasses.iv");
  const ViewSetup view = ViewSetup::prepare(scene.root.get(), SbViewportRegion(64, 48));
  renderer->render(view.root.get());
  const Image first = renderer->read();
  renderer->render(view.root.get());
  const Image second = renderer->read();
  EXPECT_TRUE(std::equal(first.data(), first.data() + 64 * 48 * 4, second.data()));
}

}  // namespace
}  // namespace ivshadow
