// A scene drawn with the plugin's nodes is freed when its application lets it go. The group
// kept SoPaths that started at itself (to its lights, camera and environment) and its tracer
// kept paths from the root: an SoPath holds a reference to every node on it, so every scene a
// group had drawn stayed in memory (about 9 MB for coloured_shadows.iv; SceneRenderFuzzer ran
// out of memory after 11,073 scenes). Each test draws a scene, lets it go and expects Coin to
// delete the group (an SoNodeSensor's delete callback).
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/sensors/SoNodeSensor.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace ivshadow {
namespace {

bool groupFreedAfterDrawing(const std::string& text, const char* renderer) {
  init();
  std::string error;
  auto offscreen = test::CheckedRenderer::create(64, 48, error);
  if (!offscreen) throw std::runtime_error(error);
  SoInput input;
  input.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) throw std::runtime_error("unreadable scene");
  root->ref();
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.apply(root);
  auto* group = static_cast<SoTransparentShadowGroup*>(search.getPath()->getTail());
  search.reset();  // its path holds the scene too
  group->renderer.setValue(renderer);
  bool freed = false;
  SoNodeSensor sensor;
  sensor.setDeleteCallback([](void* data, SoSensor*) { *static_cast<bool*>(data) = true; }, &freed);
  sensor.attach(group);
  offscreen->render(root);
  offscreen->render(root);
  root->unref();
  // Coin frees the GL resources scheduled for deletion at the context's next render.
  SoSeparator* empty = new SoSeparator;
  empty->ref();
  offscreen->render(empty);
  empty->unref();
  return freed;
}

std::string bundled(const char* name) {
  std::ifstream in(test::scenesDir() + "/" + name);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(NodeLifetime, ASceneTheGroupDrewIsFreedWhenLetGo) {
  for (const char* renderer : {"RASTER", "TRACER"}) {
    SCOPED_TRACE(renderer);
    EXPECT_TRUE(groupFreedAfterDrawing(bundled("coloured_shadows.iv"), renderer));
    // A camera and an environment inside the group, and a line set the tracer leaves to GL.
    EXPECT_TRUE(groupFreedAfterDrawing(
        "#Inventor V2.1 ascii\nTransparentShadowGroup {\n"
        "  PerspectiveCamera { position 0 0 5 }\n  Environment { ambientIntensity 0.3 }\n"
        "  DeepShadowLight { location 0 2 2 }\n"
        "  Material { diffuseColor 1 0 0 transparency 0.5 }\n  Sphere { }\n"
        "  Coordinate3 { point [ -1 -1 0, 1 1 0 ] }\n  LineSet { }\n}\n",
        renderer));
  }
}

}  // namespace
}  // namespace ivshadow
