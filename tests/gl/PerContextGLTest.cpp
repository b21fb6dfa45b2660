// PerContext: one object per GL context, freed when that context is destroyed.
#include "ivshadow/IvShadowInit.h"
#include "nodes/PerContext.h"
#include "scene/CoinRef.h"
#include "tests/gl/CheckedRenderer.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <memory>

namespace ivshadow::test {
namespace {

struct Counted {
  static int alive;
  Counted() { ++alive; }
  ~Counted() { --alive; }
};
int Counted::alive = 0;

// A scene whose one node asks `resources` for its context's object while it renders.
CoinRef<SoSeparator> sceneUsing(PerContext<Counted>& resources) {
  CoinRef<SoSeparator> root(new SoSeparator);
  auto* callback = new SoCallback;
  callback->setCallback(
      [](void* data, SoAction* action) {
        if (!action->isOfType(SoGLRenderAction::getClassTypeId())) return;
        static_cast<PerContext<Counted>*>(data)->get(
            SoGLCacheContextElement::get(action->getState()),
            [] { return std::make_unique<Counted>(); });
      },
      &resources);
  root->addChild(callback);
  return root;
}

std::unique_ptr<CheckedRenderer> makeRenderer() {
  std::string error;
  auto renderer = CheckedRenderer::create(8, 8, error);
  EXPECT_TRUE(renderer) << error;
  return renderer;
}

TEST(PerContextGLTest, AContextsObjectDiesWithTheContext) {
  init();
  PerContext<Counted> resources;
  const CoinRef<SoSeparator> scene = sceneUsing(resources);
  auto first = makeRenderer();
  auto second = makeRenderer();
  ASSERT_TRUE(first && second);
  first->render(scene.get());
  first->render(scene.get());
  EXPECT_EQ(Counted::alive, 1);  // one per context, however often it renders
  second->render(scene.get());
  EXPECT_EQ(Counted::alive, 2);
  first.reset();
  EXPECT_EQ(Counted::alive, 1);  // the other context keeps its own
  second.reset();
  EXPECT_EQ(Counted::alive, 0);
}

}  // namespace
}  // namespace ivshadow::test
