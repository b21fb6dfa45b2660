#include "raytrace/CasterScene.h"
#include "raytrace/EmbreeHandles.h"
#include "scene/SceneTriangles.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

// A grey pane of opacity 0.5 over the unit square at height z, as two triangles of one shape.
SceneTriangles paneAt(float z) {
  SceneTriangles casters;
  const float corners[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
  for (const auto& corner : corners) {
    TriangleVertex vertex{{corner[0], corner[1], z}, {0.5f, 0.5f, 0.5f, 0.5f}, {0.0f, 0.0f}};
    casters.vertices.push_back(vertex);
    casters.bounds.extendBy(SbVec3f(corner[0], corner[1], z));
  }
  casters.shapes = {0, 0};
  casters.batches.push_back({-1, 0, 6});
  casters.hasTransparent = true;
  return casters;
}

// A light that far away is a sun: the pane between it and the point takes half the light
// (monochrome model: 1 - opacity). Embree aborted the process on such rays (its ray.valid()
// limits origin and direction to about 1.8e18), and a step off the surface of 1e-5 of the
// light's distance would have jumped over the pane.
TEST(CasterScene, LightsFarBeyondFloatLightingRangeStillCastExactShadows) {
  std::string error;
  EmbreeDevice device = createEmbreeDevice(error);
  ASSERT_TRUE(device) << error;
  std::unique_ptr<CasterScene> scene = CasterScene::build(device.get(), paneAt(1.0f), error);
  ASSERT_TRUE(scene) << error;
  const glm::vec3 floorPoint(0.5f, 0.5f, 0.0f), up(0.0f, 0.0f, 1.0f);
  for (const float height : {10.0f, 1e20f, 1e30f, 3e38f}) {
    SCOPED_TRACE(height);
    const glm::vec3 through = scene->transmittance(floorPoint, up, glm::vec3(0.5f, 0.5f, height),
                                                   ShadowColourModel::Monochrome);
    // Float: exact to the rounding of one multiplication.
    EXPECT_NEAR(through.r, 0.5f, 1e-6f);
    EXPECT_NEAR(through.g, 0.5f, 1e-6f);
    // Off to the side, the ray misses the pane: all the light arrives.
    const glm::vec3 beside = scene->transmittance(floorPoint, up, glm::vec3(height, 0.5f, 1.0f),
                                                  ShadowColourModel::Monochrome);
    EXPECT_EQ(beside, glm::vec3(1.0f));
  }
}

}  // namespace
}  // namespace ivshadow
