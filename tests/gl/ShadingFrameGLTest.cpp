// A frame drawn again with nothing changed: the shading programs' uniforms are set from
// locations read once per program and context, never looked up by name, and GL is asked for
// its state only where a pass must put back what it changes: as many queries as the
// transparency mode's passes save state for, counted here from the passes themselves.
#include "gl/GlStateScope.h"
#include "ivshadow/PeelStatistics.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/GlContextTest.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <string>

namespace ivshadow::test {
namespace {

struct FrameCase {
  const char* scene;   // in iv_scenes/, with a light named Lamp
  const char* method;  // the light's method
  // The groups' transparency: COIN_BLENDING draws the children once (a peeling separator
  // among them peels its own), PEELED (the default) peels them where the view shows
  // transparency.
  const char* transparency;
  // The method of the peeling separator inside the group that peels its children ("": no
  // separator): inside a group AUTO and TRACER list the fragments, DUAL and FRONT_TO_BACK peel.
  const char* separatorMethod;
};

// The queries a GlStateScope saving `changes` makes, with `units` texture units of `targets`
// bindings each (GlStateScope::queriesFor, which the glGet* calls the counter counts follow).
int scopeQueries(unsigned changes, int units = 0, int targets = 1) {
  GlStateScope::Textures textures;
  textures.units.assign(std::size_t(units), 0);
  textures.targets.assign(std::size_t(targets), 0u);
  return GlStateScope::queriesFor(changes, textures);
}

// A steady frame of a group: its shading program bound (the current program read back, 1)
// and the two array textures of its maps or traced shadows bound on units of their own.
int shadingQueries() {
  return 1 + scopeQueries(0u, 2);
}

// A peeling (nodes/DepthPeeling.cpp, gl/PeelPass.cpp, gl/FragmentListPass.cpp)
// as its statistics say it went: the opaque pass binds its variant and saves the storage
// binding; the transparent surfaces then go into fragment lists (a variant bound and the
// bindings saved a list pass, the fragments stored counted from a read-back under a
// PixelStoreScope, which saves the pack and unpack buffers, and one resolve that saves what it
// draws with) or are peeled: the targets saved once, each pass a variant bound and, dual, every
// pass after the first compositing its back layer under a scope.
int peelingQueries(const PeelStatistics& peeling, bool dual) {
  using S = GlStateScope;
  int queries = 1 + scopeQueries(S::kStorageBuffers);
  if (peeling.listPasses > 0) {
    queries += peeling.listPasses *
               (1 + scopeQueries(S::kFramebuffers | S::kStorageBuffers | S::kImageBindings));
    queries += 2;                        // the PixelStoreScope
    queries += scopeQueries(S::kDepth);  // GL's depth state, put back after the list pass
    queries += scopeQueries(S::kFramebuffers | S::kViewport | S::kProgram | S::kVertexArray |
                            S::kStorageBuffers | S::kImageBindings | S::kBlendFunction | S::kDepth |
                            S::kFragmentTests);
  } else if (peeling.passes > 0) {
    queries +=
        scopeQueries(S::kFramebuffers | S::kViewport | S::kProgram | S::kVertexArray |
                         S::kStorageBuffers | S::kBlendFunction | S::kDepth | S::kFragmentTests,
                     3);
    for (int pass = 0; pass < peeling.passes; ++pass)
      queries +=
          1 + (dual && pass > 0 ? scopeQueries(S::kFramebuffers | S::kProgram | S::kVertexArray |
                                                   S::kBlendFunction | S::kFragmentTests,
                                               1)
                                : 0);
  }
  return queries;
}

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
  const std::string separatorMethod = GetParam().separatorMethod;
  if (!separatorMethod.empty()) {
    SoSearchAction separator;
    separator.setName("Glasses");
    separator.apply(loaded.root.get());
    ASSERT_NE(separator.getPath(), nullptr);
    separator.getPath()->getTail()->set(("method " + separatorMethod).c_str());
  }
  const ViewSetup view = ViewSetup::prepare(loaded.root.get(), SbViewportRegion(64, 64));
  // The first frame builds the maps and links the programs (reading their locations).
  renderer().render(view.root.get());
  // Counted apart from the frame's (it asks GL for the clip distances).
  const int shading = shadingQueries();
  GlCallCounter counter;
  renderer().render(view.root.get());
  const long queries = counter.queries();
  EXPECT_EQ(counter.uniformLookups(), 0);
  const PeelStatistics peeling = collectPeelStatistics(view.root.get());
  const bool peeled = std::string(GetParam().transparency) == "PEELED" || !separatorMethod.empty();
  // Whatever the mode, the view shows its glasses: the peeling has them to peel.
  if (peeled) EXPECT_GT(peeling.passes, 0);
  // The group peels dual; a separator as its method says.
  const bool dual = separatorMethod != "FRONT_TO_BACK";
  // A separator in a group shades with the group's program: it checks one is current (1).
  const int expected =
      shading + (peeled ? peelingQueries(peeling, dual) : 0) + (separatorMethod.empty() ? 0 : 1);
  EXPECT_EQ(queries, expected) << "peel passes " << peeling.passes << ", of them list passes "
                               << peeling.listPasses;
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ShadingFrameGLTest,
    // Each transparency mode with both kinds of shadow: the group's own peeling (PEELED), and
    // a peeling separator's inside a group that leaves transparency to Coin, by each way a
    // separator in a group peels (its default lists the fragments).
    ::testing::Values(FrameCase{"coloured_shadows.iv", "MAP", "COIN_BLENDING", ""},
                      FrameCase{"coloured_shadows.iv", "RAYS", "COIN_BLENDING", ""},
                      FrameCase{"coloured_shadows.iv", "MAP", "PEELED", ""},
                      FrameCase{"coloured_shadows.iv", "RAYS", "PEELED", ""},
                      FrameCase{"peeled_glasses.iv", "MAP", "COIN_BLENDING", "AUTO"},
                      FrameCase{"peeled_glasses.iv", "RAYS", "COIN_BLENDING", "AUTO"},
                      FrameCase{"peeled_glasses.iv", "MAP", "COIN_BLENDING", "DUAL"},
                      FrameCase{"peeled_glasses.iv", "MAP", "COIN_BLENDING", "FRONT_TO_BACK"}),
    [](const ::testing::TestParamInfo<FrameCase>& info) {
      std::string name = std::string(info.param.scene) + info.param.method +
                         info.param.transparency + info.param.separatorMethod;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

}  // namespace
}  // namespace ivshadow::test
