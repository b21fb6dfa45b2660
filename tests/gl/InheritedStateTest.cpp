// State set above a SoTransparentShadowGroup, outside it, reaches its casters in both methods
// (InheritedStateCases.h), and a change there is seen in the next frame.
#include "image_files/ImageComparison.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/InheritedStateCases.h"

#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

#include <gtest/gtest.h>

#include <string>

namespace ivshadow::test {
namespace {

// As in DeepShadowTest and RayShadowTest: per-pixel float shading rounded once to 8 bits (half
// a step), the map sampled inside each shadow (every edge is left out by the cases' 2-pixel
// margins) or the transmittance traced exactly and stored as a 16-bit float (a quarter step
// at most). One 8-bit step bounds both.
constexpr double kTolerance = 1.0;

struct MethodCase {
  InheritedCase state;
  std::string method;
};

void PrintTo(const MethodCase& c, std::ostream* os) {
  *os << c.state.name << " with " << c.method;
}

std::vector<MethodCase> methodCases() {
  std::vector<MethodCase> result;
  for (const InheritedCase& c : inheritedStateCases())
    for (const char* method : {"MAP", "RAYS"}) result.push_back({c, method});
  return result;
}

std::string methodCaseName(const ::testing::TestParamInfo<MethodCase>& info) {
  return info.param.state.name + "_" + info.param.method;
}

class InheritedStateShadows : public ::testing::TestWithParam<MethodCase> {};

TEST_P(InheritedStateShadows, MatchesThePicture) {
  ShadowScene scene = GetParam().state.scene;
  scene.method = GetParam().method;
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  const std::string failure = compareWithExpectation(image, GetParam().state.expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

INSTANTIATE_TEST_SUITE_P(Cases, InheritedStateShadows, ::testing::ValuesIn(methodCases()),
                         methodCaseName);

// The Material above the group turned opaque between two frames: the group is not notified
// (the material is not below it), yet the next frame casts the opaque glass's black shadow;
// a third, unchanged frame builds nothing.
class InheritedStateChange : public ::testing::TestWithParam<std::string> {};

TEST_P(InheritedStateChange, AMaterialChangedAboveTheGroupIsSeenInTheNextFrame) {
  InheritedCase material;
  for (const InheritedCase& c : inheritedStateCases())
    if (c.name == "MaterialAbove") material = c;
  ASSERT_FALSE(material.name.empty());
  material.scene.method = GetParam();
  SoSeparator* root = readIv(material.scene.text());
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  std::string failure = compareWithExpectation(renderer->read(), material.expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << "half transparent: " << failure;
  const DeepShadowStatistics before = collectDeepShadowStatistics(root);

  auto* above = static_cast<SoMaterial*>(SoNode::getByName("Above"));
  ASSERT_NE(above, nullptr);
  above->transparency.setValue(0.0f);
  renderer->render(root);
  ShadowScene opaque;
  opaque.filters = {kRedGlass};
  opaque.filters[0].transparency = 0.0;
  const ShadowPicture blocked{&opaque, ColourModel::Saturate};
  failure = compareWithExpectation(renderer->read(), blocked, kTolerance);
  EXPECT_TRUE(failure.empty()) << "made opaque above the group: " << failure;
  const DeepShadowStatistics after = collectDeepShadowStatistics(root);
  if (GetParam() == "MAP") {
    EXPECT_EQ(after.rebuilds, before.rebuilds + 1);
  } else {
    EXPECT_EQ(after.rayFrames, before.rayFrames + 1);
  }

  renderer->render(root);
  const DeepShadowStatistics still = collectDeepShadowStatistics(root);
  EXPECT_EQ(still.rebuilds, after.rebuilds);  // nothing changed: nothing is built again
  EXPECT_EQ(still.rayFrames, after.rayFrames);
  EXPECT_EQ(still.bvhBuilds, after.bvhBuilds);
  root->unref();
}

// The transform above the group moved between two frames: casters and lights are kept in the
// group's coordinates, so no caster is taken again and no map is built again (RAYS traces
// again: the view of the group changed); the picture moves with the transform.
TEST_P(InheritedStateChange, ATransformMovedAboveTheGroupTakesNoCastersAgain) {
  InheritedCase moved;
  for (const InheritedCase& c : inheritedStateCases())
    if (c.name == "TransformAbove") moved = c;
  ASSERT_FALSE(moved.name.empty());
  moved.scene.method = GetParam();
  SoSeparator* root = readIv(moved.scene.text());
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  renderer->render(root);
  std::string failure = compareWithExpectation(renderer->read(), moved.expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << "before: " << failure;
  const DeepShadowStatistics before = collectDeepShadowStatistics(root);

  auto* transform = static_cast<SoTransform*>(SoNode::getByName("Move"));
  ASSERT_NE(transform, nullptr);
  transform->translation.setValue(-0.3f, 0.2f, 0.0f);
  renderer->render(root);
  ShadowScene glass;
  glass.filters = {kRedGlass};
  const ShadowPicture picture{&glass, ColourModel::Saturate};
  failure = compareWithExpectation(
      renderer->read(),
      [&picture](int px, int py) {
        return picture.at((floorX(px) + 0.3) / 0.5, (floorY(py) - 0.2) / 0.5, 0.01 / 0.5);
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << "moved: " << failure;
  const DeepShadowStatistics after = collectDeepShadowStatistics(root);
  EXPECT_EQ(after.rebuilds, before.rebuilds);
  EXPECT_EQ(after.bvhBuilds, before.bvhBuilds);
  EXPECT_EQ(after.bvhRefits, before.bvhRefits);
  if (GetParam() == "RAYS") EXPECT_EQ(after.rayFrames, before.rayFrames + 1);
  root->unref();
}

INSTANTIATE_TEST_SUITE_P(Methods, InheritedStateChange, ::testing::Values("MAP", "RAYS"));

// One group under two paths, each with its own Material above, each half the picture's size:
// each instance casts with its own material (the left one red and half transparent, the right
// one opaque), and a warning says that the casters are taken again for each path.
TEST(InheritedState, AGroupInstancedUnderTwoMaterialsCastsWithEach) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene.filters[0].ownMaterial = false;
  std::string text = scene.text();
  // The scene's group, turned into two instances: the DEF at its first use, USE at the second.
  const std::string open = "  DEF Group TransparentShadowGroup {";
  const std::size_t start = text.find(open);
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = text.rfind("}\n");  // the root's closing brace
  const std::string group = text.substr(start, end - start);
  const std::string glass = "Material { ambientColor 0 0 0 specularColor 0 0 0 ";
  text = text.substr(0, start) + "  Separator {\n    Transform { translation -0.6 0 0 " +
         "scaleFactor 0.5 0.5 0.5 }\n    " + glass + "diffuseColor 1 0 0 transparency 0.5 }\n" +
         group + "  }\n  Separator {\n    Transform { translation 0.6 0 0 scaleFactor 0.5 0.5 " +
         "0.5 }\n    " + glass + "diffuseColor 1 0 0 transparency 0 }\n    USE Group\n  }\n}\n";
  SoSeparator* root = readIv(text);
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  CoinMessageCapture messages;
  renderer->render(root);
  renderer->render(root);
  const Image image = renderer->read();
  ShadowScene half = scene;
  half.filters[0].ownMaterial = true;
  ShadowScene opaque = half;
  opaque.filters[0].transparency = 0.0;
  const std::string failure = compareWithExpectation(
      image,
      [&](int px, int py) {
        const double x = floorX(px), y = floorY(py);
        const bool left = x < 0.0;
        const ShadowPicture picture{left ? &half : &opaque, ColourModel::Saturate};
        // Each instance's floor spans 1 about its centre; the gap between is background.
        return picture.at((x - (left ? -0.6 : 0.6)) / 0.5, y / 0.5, 0.01 / 0.5);
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
  int warnings = 0;
  for (const CoinMessageCapture::Message& message : messages.messages())
    if (message.text.find("rendered through several paths") != std::string::npos) ++warnings;
  EXPECT_EQ(warnings, 1);
  root->unref();
}

}  // namespace
}  // namespace ivshadow::test
