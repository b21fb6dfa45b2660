// CasterScene::update: moved casters keep their tree (a refit) and are traced where they are
// now; other triangles need a new scene; a recolouring changes only colours.
#include "ivshadow/IvShadowInit.h"
#include "raytrace/CasterScene.h"
#include "raytrace/EmbreeHandles.h"
#include "scene/CoinRef.h"
#include "scene/SceneTriangles.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTranslation.h>

#include <gtest/gtest.h>

namespace ivshadow::test {
namespace {

// 1 - 0.5 and a product with 1 are exact in float; the tracer's offsets move no hit.
constexpr float kExact = 1e-6f;

// A 2 x 2 square in the plane z = 0 around the translation, of opacity 0.5.
struct Glass {
  CoinRef<SoSeparator> root{new SoSeparator};
  SoTranslation* translation = new SoTranslation;
  SoMaterial* material = new SoMaterial;
  SoFaceSet* faces = new SoFaceSet;
  SoCoordinate3* coordinates = new SoCoordinate3;

  Glass() {
    material->transparency = 0.5f;
    const SbVec3f corners[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    coordinates->point.setValues(0, 4, corners);
    faces->numVertices = 4;
    root->addChild(translation);
    root->addChild(material);
    root->addChild(coordinates);
    root->addChild(faces);
  }
};

// Light crossing z = 0 at (x, 0.3): from below the square to a light above it, off the
// diagonal that splits the square into two triangles (a ray along a shared edge may meet both).
glm::vec3 through(const CasterScene& scene, float x) {
  return scene.transmittance({x, 0.3f, -1.0f}, {0.0f, 0.0f, 1.0f}, {x, 0.3f, 1.0f},
                             ShadowColourModel::Monochrome);
}

class CasterSceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Registers the nodes and lets the casters' SoCallbackAction track SoShadowStyle.
    init();
    std::string error;
    device_ = createEmbreeDevice(error);
    ASSERT_TRUE(device_) << error;
  }
  // The Embree scene of `glass` as it is now.
  std::unique_ptr<CasterScene> build(const Glass& glass) {
    std::string error;
    auto scene = CasterScene::build(device_.get(), extractShadowCasters(glass.root.get()), error);
    EXPECT_TRUE(scene) << error;
    return scene;
  }
  EmbreeDevice device_;
};

TEST_F(CasterSceneTest, MovedCastersAreRefittedAndTracedWhereTheyAreNow) {
  Glass glass;
  const auto scene = build(glass);
  ASSERT_TRUE(scene);
  EXPECT_NEAR(through(*scene, 0.0f).r, 0.5f, kExact);
  EXPECT_NEAR(through(*scene, 5.0f).r, 1.0f, kExact);

  glass.translation->translation = SbVec3f(5.0f, 0.0f, 0.0f);
  EXPECT_EQ(scene->update(extractShadowCasters(glass.root.get())), CasterScene::Update::Refit);
  // The refitted tree finds the square at x = 5 and no longer at x = 0.
  EXPECT_NEAR(through(*scene, 5.0f).r, 0.5f, kExact);
  EXPECT_NEAR(through(*scene, 0.0f).r, 1.0f, kExact);
}

TEST_F(CasterSceneTest, RecolouringKeepsTheGeometry) {
  Glass glass;
  const auto scene = build(glass);
  ASSERT_TRUE(scene);
  glass.material->transparency = 0.75f;
  EXPECT_EQ(scene->update(extractShadowCasters(glass.root.get())), CasterScene::Update::Colours);
  // Opacity 0.25 now lets 0.75 through.
  EXPECT_NEAR(through(*scene, 0.0f).r, 0.75f, kExact);
}

TEST_F(CasterSceneTest, OtherTrianglesNeedANewScene) {
  Glass glass;
  const auto scene = build(glass);
  ASSERT_TRUE(scene);
  // A fifth corner makes a pentagon: three triangles where there were two.
  glass.coordinates->point.set1Value(4, SbVec3f(0.0f, 2.0f, 0.0f));
  glass.faces->numVertices = 5;
  EXPECT_EQ(scene->update(extractShadowCasters(glass.root.get())), CasterScene::Update::Rebuild);
  // A rebuild is the caller's to do: the scene still holds the square.
  EXPECT_NEAR(through(*scene, 0.0f).r, 0.5f, kExact);
}

}  // namespace
}  // namespace ivshadow::test
