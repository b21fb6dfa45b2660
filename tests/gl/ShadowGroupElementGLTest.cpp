// ShadowGroupElement: the group's shading is in the traversal state while its children render,
// and gone once the group's separator pops, whatever comes after it.
#include "nodes/ShadowGroupElement.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/CoinRef.h"
#include "tests/gl/GlContextTest.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <vector>

namespace ivshadow::test {
namespace {

class ShadowGroupElementGLTest : public GlContextTest {};

// What each probe saw, in traversal order: whether a group's shading was active.
struct Seen {
  std::vector<bool> active;
  std::vector<bool> capturing;
};

SoCallback* probe(Seen& seen) {
  auto* callback = new SoCallback;
  callback->setCallback(
      [](void* data, SoAction* action) {
        if (!action->isOfType(SoGLRenderAction::getClassTypeId())) return;
        auto* record = static_cast<Seen*>(data);
        record->active.push_back(ShadowGroupElement::activeGroup(action->getState()) != nullptr);
        record->capturing.push_back(ShadowGroupElement::capturing(action->getState()));
      },
      &seen);
  return callback;
}

// A camera, a probe, a group holding one light of `method`, a probe and a cube, a probe.
CoinRef<SoSeparator> probedScene(int method, Seen& before, Seen& inside, Seen& after) {
  CoinRef<SoSeparator> root(new SoSeparator);
  root->addChild(new SoOrthographicCamera);
  root->addChild(probe(before));
  auto* group = new SoTransparentShadowGroup;
  group->renderer = SoTransparentShadowGroup::RASTER;  // the GL passes this test watches
  auto* light = new SoDeepShadowLight;
  light->method = method;
  group->addChild(light);
  group->addChild(probe(inside));
  group->addChild(new SoCube);
  root->addChild(group);
  root->addChild(probe(after));
  return root;
}

TEST_F(ShadowGroupElementGLTest, HoldsTheGroupOnlyWhileItsChildrenRender) {
  Seen before, inside, after;
  // MAP: no capture pass, so the children render once.
  renderer().render(probedScene(SoDeepShadowLight::MAP, before, inside, after).get());
  EXPECT_EQ(before.active, std::vector<bool>{false});
  EXPECT_EQ(inside.active, std::vector<bool>{true});
  EXPECT_EQ(after.active, std::vector<bool>{false});
  EXPECT_EQ(inside.capturing, std::vector<bool>{false});
}

TEST_F(ShadowGroupElementGLTest, SaysCapturingWhileRaysLightsCapture) {
  Seen before, inside, after;
  renderer().render(probedScene(SoDeepShadowLight::RAYS, before, inside, after).get());
  // An opaque cube: one capture (its opaque layer), then the shading pass.
  EXPECT_EQ(inside.capturing, (std::vector<bool>{true, false}));
  EXPECT_EQ(inside.active, (std::vector<bool>{false, true}));
  EXPECT_EQ(after.capturing, std::vector<bool>{false});
}

}  // namespace
}  // namespace ivshadow::test
