// State set above a group, outside it: the reference's pictures of the inherited-state cases
// (InheritedStateCases.h), the casters taken along a path, and the key that tells a group its
// inherited state changed.
#include "ivshadow/IvShadowInit.h"
#include "scene/CoinRef.h"
#include "scene/InheritedState.h"
#include "scene/SceneTriangles.h"
#include "tests/gl/InheritedStateCases.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoComplexity.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace ivshadow::test {
namespace {

// Per-pixel float shading rounded once to 8 bits: half a step of rounding plus float error
// far below a step. One step bounds it (the same bound as the GL tests).
constexpr double kTolerance = 1.0;

class ReferenceInheritedState : public ::testing::TestWithParam<InheritedCase> {};

TEST_P(ReferenceInheritedState, MatchesThePicture) {
  const Image image = referenceIv(GetParam().scene.text(), ShadowScene::kSize);
  const std::string failure = compareWithExpectation(image, GetParam().expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

INSTANTIATE_TEST_SUITE_P(Cases, ReferenceInheritedState, ::testing::ValuesIn(inheritedStateCases()),
                         inheritedCaseName);

// The path from `root` to its node named `name`.
CoinRef<SoPath> pathTo(SoNode* root, const char* name) {
  SoSearchAction search;
  search.setName(name);
  search.apply(root);
  EXPECT_NE(search.getPath(), nullptr) << name;
  return CoinRef<SoPath>(search.getPath() ? search.getPath()->copy() : nullptr);
}

const char kGroupUnderState[] =
    "#Inventor V2.1 ascii\nSeparator {\n"
    "  DEF Fine Complexity { value 0.1 }\n"
    "  Separator { Complexity { value 1 } }\n"  // off the path: its state ends with it
    "  Transform { translation 10 20 30 scaleFactor 2 2 2 }\n"
    "  DEF Glass Material { diffuseColor 1 0 0 transparency 0.25 }\n"
    "  Cube { }\n"  // outside the group, left of it: not a caster
    "  DEF Group TransparentShadowGroup {\n"
    "    Translation { translation 0 0 0.5 }\n"
    "    Sphere { radius 1 }\n"
    "  }\n"
    "}\n";

TEST(InheritedStateCasters, ComeFromTheStateAboveInTheGroupsCoordinates) {
  SoSeparator* root = readIv(kGroupUnderState);
  const CoinRef<SoPath> path = pathTo(root, "Group");
  ASSERT_TRUE(path);
  const SceneTriangles casters = extractShadowCasters(path.get());
  // Complexity 0.1: the octahedron of Coin's sphere at 4 slices and 3 stacks, 8 triangles
  // (the cube outside the group adds none).
  EXPECT_EQ(casters.triangleCount(), 8u);
  // Transparency 0.25 and red from the material above.
  ASSERT_FALSE(casters.vertices.empty());
  EXPECT_FLOAT_EQ(casters.vertices[0].colour[0], 1.0f);
  EXPECT_FLOAT_EQ(casters.vertices[0].colour[1], 0.0f);
  EXPECT_FLOAT_EQ(casters.vertices[0].colour[3], 0.75f);
  EXPECT_TRUE(casters.hasTransparent);
  // In the group's coordinates: the unit sphere raised by 0.5, whatever the transform above.
  const SbVec3f low = casters.bounds.getMin(), high = casters.bounds.getMax();
  const float expectedLow[3] = {-1.0f, -1.0f, -0.5f}, expectedHigh[3] = {1.0f, 1.0f, 1.5f};
  for (int i = 0; i < 3; ++i) {
    // The inverse of the model matrix at the group, applied in single precision.
    EXPECT_NEAR(low[i], expectedLow[i], 1e-5) << i;
    EXPECT_NEAR(high[i], expectedHigh[i], 1e-5) << i;
  }
  // From a default state (the group alone), the same sphere has Coin's default complexity
  // 0.5: 15 slices and stacks, 2 x 15 caps + 2 x 15 x 12 quads' triangles.
  EXPECT_EQ(extractShadowCasters(path->getTail()).triangleCount(), 15u * 2u + 15u * 12u * 2u);
  root->unref();
}

TEST(InheritedStateCasters, ShapesDrawnAsLinesOrNotAtAllCastNothing) {
  SoSeparator* root = readIv(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  DrawStyle { style LINES }\n"
      "  DEF Group TransparentShadowGroup {\n"
      "    DEF Outline Cube { }\n"
      "    Separator { DrawStyle { style INVISIBLE } DEF Hidden Cube { } }\n"
      "    Separator { DrawStyle { style POINTS } DEF Dots Cube { } }\n"
      "    Separator { DrawStyle { style FILLED } DEF Solid Cube { } }\n"
      "  }\n}\n");
  const CoinRef<SoPath> path = pathTo(root, "Group");
  ASSERT_TRUE(path);
  const SceneTriangles casters = extractShadowCasters(path.get());
  EXPECT_EQ(casters.triangleCount(), 12u);  // the filled cube only
  // Named, so that the group warns that they cast nothing; the invisible one is not drawn.
  EXPECT_EQ(casters.withoutTriangles, (std::vector<std::string>{"Cube 'Outline'", "Cube 'Dots'"}));
  root->unref();
}

TEST(InheritedStateCasters, AShadowStyleAboveIsHonouredUntilOneBelowChangesIt) {
  SoSeparator* root = readIv(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  ShadowStyle { style SHADOWED }\n"
      "  DEF Group TransparentShadowGroup {\n"
      "    Cube { }\n"
      "    Separator { ShadowStyle { style CASTS_SHADOW } Cube { } }\n"
      "  }\n}\n");
  const CoinRef<SoPath> path = pathTo(root, "Group");
  ASSERT_TRUE(path);
  EXPECT_EQ(extractShadowCasters(path.get()).triangleCount(), 12u);
  root->unref();
}

// InheritedState::capture at the group, for each traversal of `root` by a SoCallbackAction,
// passed to `use` while the traversal's state is alive.
void atGroup(SoNode* root, const std::function<void(SoState*)>& use) {
  SoCallbackAction action;
  auto callback = [](void* data, SoCallbackAction* a, const SoNode* node) {
    if (node->getName() == SbName("Group"))
      (*static_cast<const std::function<void(SoState*)>*>(data))(a->getState());
    return SoCallbackAction::CONTINUE;
  };
  action.addPreCallback(SoNode::getClassTypeId(), callback,
                        const_cast<void*>(static_cast<const void*>(&use)));
  action.apply(root);
}

TEST(InheritedStateKey, ChangesWithStateAboveAndNotWithTransforms) {
  SoSeparator* root = readIv(kGroupUnderState);
  InheritedState key;
  atGroup(root, [&key](SoState* state) { key = InheritedState::capture(state); });
  ASSERT_FALSE(key.empty());
  const auto matchesNow = [&]() {
    bool matches = false;
    atGroup(root, [&](SoState* state) { matches = key.matches(state); });
    return matches;
  };
  EXPECT_TRUE(matchesNow());  // nothing changed

  // A transform above moves the group's lights with its casters: not a change of casters.
  SoSearchAction search;
  search.setName("Group");
  search.apply(root);
  ASSERT_NE(search.getPath(), nullptr);
  auto* transformParent = static_cast<SoSeparator*>(search.getPath()->getHead());
  auto* transform = static_cast<SoTransform*>(transformParent->getChild(2));
  transform->translation.setValue(1.0f, 2.0f, 3.0f);
  EXPECT_TRUE(matchesNow());

  auto* glass = static_cast<SoMaterial*>(SoNode::getByName("Glass"));
  ASSERT_NE(glass, nullptr);
  glass->transparency.setValue(0.5f);
  EXPECT_FALSE(matchesNow());  // the material above changed
  atGroup(root, [&key](SoState* state) { key = InheritedState::capture(state); });
  EXPECT_TRUE(matchesNow());

  auto* complexity = static_cast<SoComplexity*>(SoNode::getByName("Fine"));
  ASSERT_NE(complexity, nullptr);
  complexity->value.setValue(0.9f);
  EXPECT_FALSE(matchesNow());  // the complexity above changed
  root->unref();
}

TEST(InheritedStateKey, AnEmptyKeyMatchesNothing) {
  init();
  SoSeparator* root = readIv(kGroupUnderState);
  const InheritedState empty;
  bool matches = true;
  atGroup(root, [&](SoState* state) { matches = empty.matches(state); });
  EXPECT_FALSE(matches);
  root->unref();
}

}  // namespace
}  // namespace ivshadow::test
