// A frame drawn again with nothing changed: the shading programs' uniforms are set from
// locations read once per program and context, never looked up by name.
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/SceneLoader.h"
#include "scene/ViewSetup.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/GlContextTest.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <iostream>
#include <string>

namespace ivshadow::test {
namespace {

struct FrameCase {
  const char* scene;   // in iv_scenes/, with a light named Lamp
  const char* method;  // the light's method
  // The groups' transparency: COIN_BLENDING draws the children once, PEELED (the default)
  // peels them where the view shows transparency.
  const char* transparency;
  // State queries the frame may make, or -1 where the count is only reported (peeling's
  // passes read what Coin left at each of them).
  int queries;
};

class ShadingFrameGLTest : public GlContextTest, public ::testing::WithParamInterface<FrameCase> {};

TEST_P(ShadingFrameGLTest, ASteadyFrameLooksUpNoUniform) {
  const LoadedScene loaded = loadScene(scenesDir() + "/" + GetParam().scene);
  SoSearchAction search;
  search.setName("Lamp");
  search.apply(loaded.root.get());
  ASSERT_NE(search.getPath(), nullptr);
  search.getPath()->getTail()->set((std::string("method ") + GetParam().method).c_str());
  SoSearchAction groups;
  groups.setType(SoTransparentShadowGroup::getClassTypeId());
  groups.setInterest(SoSearchAction::ALL);
  groups.apply(loaded.root.get());
  for (int i = 0; i < groups.getPaths().getLength(); ++i)
    groups.getPaths()[i]->getTail()->set(
        (std::string("transparency ") + GetParam().transparency + " renderer RASTER").c_str());
  const ViewSetup view = ViewSetup::prepare(loaded.root.get(), SbViewportRegion(64, 64));
  // The first frame builds the maps and links the programs (reading their locations).
  renderer().render(view.root.get());
  GlCallCounter counter;
  renderer().render(view.root.get());
  EXPECT_EQ(counter.uniformLookups(), 0);
  if (GetParam().queries >= 0) EXPECT_EQ(counter.queries(), GetParam().queries);
  std::cout << GetParam().scene << " " << GetParam().method << ": " << counter.queries()
            << " state queries in a steady frame\n";
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ShadingFrameGLTest,
    // One light: the program Coin made current (1), the active texture
    // unit and the two units bound for its map or its traced shadows (3).
    // Peeling (the groups' default) reads what Coin left at each pass.
    ::testing::Values(FrameCase{"coloured_shadows.iv", "MAP", "COIN_BLENDING", 4},
                      FrameCase{"coloured_shadows.iv", "RAYS", "COIN_BLENDING", 4},
                      FrameCase{"coloured_shadows.iv", "MAP", "PEELED", -1},
                      FrameCase{"coloured_shadows.iv", "RAYS", "PEELED", -1},
                      FrameCase{"peeled_glasses.iv", "MAP", "COIN_BLENDING", -1},
                      FrameCase{"peeled_glasses.iv", "RAYS", "COIN_BLENDING", -1}),
    [](const ::testing::TestParamInfo<FrameCase>& info) {
      std::string name =
          std::string(info.param.scene) + info.param.method + info.param.transparency;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

}  // namespace
}  // namespace ivshadow::test
