// The peel passes leave GL's depth state as they found it. FreeCAD's view sets GL_LESS itself,
// not through Coin's depth element, and draws a selected face's highlight before drawing the
// whole shape again at the same depth, so that the first drawing stays in front; its nodes
// after a peeling group (the "on top" selection, the sketcher's and the dragger's editing root)
// draw so. The peel passes set Coin's depth element for their own drawing inside a state push;
// its pop sent the depth function Coin believed in force (LEQUAL, its default), and the shape
// drawn again after the group covered the first drawing. As a RAYS capture does
// (nodes/RayMethod.cpp), peelSubgraph now puts back the depth state GL had.
#include "ivshadow/PeelStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/CoinRef.h"
#include "tests/gl/FreeCadViewRoot.h"
#include "tests/gl/GlContextTest.h"

#include <epoxy/gl.h>

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>

#include <array>
#include <ostream>
#include <string>

namespace ivshadow::test {
namespace {

class PeelDepthFunctionGLTest : public GlContextTest {};

// What GL's depth state was where the probe after the peeling node ran.
struct DepthSeen {
  GLint function = 0;
  GLboolean writeMask = GL_FALSE;
  bool ran = false;
};

// A quad over the square [x0, x1] x [-1, 1] at height z (the camera looks down -z).
SoSeparator* quad(float x0, float x1, float z, SoNode* look) {
  auto* separator = new SoSeparator;
  separator->addChild(look);
  auto* coordinates = new SoCoordinate3;
  const SbVec3f corners[] = {{x0, -1, z}, {x1, -1, z}, {x1, 1, z}, {x0, 1, z}};
  coordinates->point.setValues(0, 4, corners);
  separator->addChild(coordinates);
  separator->addChild(new SoFaceSet);
  return separator;
}

SoSeparator* unlit(const SbColor& colour, float x0, float x1, float z) {
  auto* look = new SoGroup;
  auto* model = new SoLightModel;
  model->model = SoLightModel::BASE_COLOR;
  look->addChild(model);
  auto* base = new SoBaseColor;
  base->rgb = colour;
  look->addChild(base);
  return quad(x0, x1, z, look);
}

// The peeled children: an opaque grey floor and a 50 % transparent red quad over its left half,
// so that the peel passes run (a view without a transparent surface ends after the opaque one).
void addPeeledChildren(SoGroup* parent) {
  auto* floor = new SoMaterial;
  floor->diffuseColor.setValue(0.5f, 0.5f, 0.5f);
  parent->addChild(quad(-1, 1, 0, floor));
  auto* glass = new SoMaterial;
  glass->diffuseColor.setValue(1, 0, 0);
  glass->transparency = 0.5f;
  parent->addChild(quad(-1, 0, 0.5f, glass));
}

enum class Peeler { Group, Dual, FrontToBack, FragmentLists };

void PrintTo(Peeler peeler, std::ostream* out) {
  const char* names[] = {"group PEELED", "separator DUAL", "separator FRONT_TO_BACK",
                         "separator FRAGMENT_LISTS"};
  *out << names[int(peeler)];
}

SoGroup* peelingNode(Peeler peeler) {
  if (peeler == Peeler::Group) {
    auto* group = new SoTransparentShadowGroup;
    group->renderer = SoTransparentShadowGroup::RASTER;  // the GL passes this test watches
    group->transparency = SoTransparentShadowGroup::PEELED;
    auto* light = new SoDeepShadowLight;
    light->location.setValue(0, 0, 3);
    light->method.set("MAP");
    group->addChild(light);
    return group;
  }
  auto* separator = new SoPeelingSeparator;
  separator->method = peeler == Peeler::Dual          ? SoPeelingSeparator::DUAL
                      : peeler == Peeler::FrontToBack ? SoPeelingSeparator::FRONT_TO_BACK
                                                      : SoPeelingSeparator::FRAGMENT_LISTS;
  return separator;
}

int peelPasses(Peeler peeler, SoNode* node) {
  return peeler == Peeler::Group
             ? static_cast<SoTransparentShadowGroup*>(node)->getPeelStatistics().passes
             : static_cast<SoPeelingSeparator*>(node)->getStatistics().passes;
}

const SbColor kFirst(0, 1, 0);
const SbColor kAgain(0, 0, 1);

class PeelDepthFunctionCaseGLTest : public PeelDepthFunctionGLTest,
                                    public ::testing::WithParamInterface<Peeler> {};

TEST_P(PeelDepthFunctionCaseGLTest, GlDepthStateAfterThePeelingIsTheOneBefore) {
  const Peeler peeler = GetParam();
  CoinRef<SoSeparator> root = freeCadViewRoot();
  SoGroup* peeling = peelingNode(peeler);
  addPeeledChildren(peeling);
  root->addChild(peeling);
  DepthSeen seen;
  auto* probe = new SoCallback;
  probe->setCallback(
      [](void* data, SoAction* action) {
        if (!action->isOfType(SoGLRenderAction::getClassTypeId())) return;
        auto* record = static_cast<DepthSeen*>(data);
        glGetIntegerv(GL_DEPTH_FUNC, &record->function);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &record->writeMask);
        record->ran = true;
      },
      &seen);
  root->addChild(probe);
  // After the group, one surface drawn twice at the same depth, over the right half (the
  // opaque floor's): first green, as FreeCAD draws a highlight, then blue, as it draws the
  // whole shape again.
  root->addChild(unlit(kFirst, 0.2f, 0.8f, 0.25f));
  root->addChild(unlit(kAgain, 0.2f, 0.8f, 0.25f));

  renderer().render(root.get());
  const Image picture = renderer().read();

  // The transparent quad was peeled: the passes this test is about ran.
  EXPECT_GT(peelPasses(peeler, peeling), 0);
  ASSERT_TRUE(seen.ran);
  EXPECT_EQ(seen.function, GL_LESS)
      << "GL's depth function after the peeling, 0x" << std::hex << seen.function;
  // Coin's default, which the callback left alone.
  EXPECT_EQ(seen.writeMask, GL_TRUE);
  // Under GL_LESS the second drawing at the same depth fails the test: the first one's colour
  // stays, exactly (unlit, 0 or 1 per channel).
  const std::uint8_t* p = picture.pixel(picture.width() * 3 / 4, picture.height() / 2);
  EXPECT_EQ((std::array<int, 3>{p[0], p[1], p[2]}), (std::array<int, 3>{0, 255, 0}))
      << "the surface drawn first, then again at the same depth, after the peeling";
}

// Test names: no spaces.
std::string peelerName(const ::testing::TestParamInfo<Peeler>& info) {
  const char* const names[] = {"GroupPeeled", "SeparatorDual", "SeparatorFrontToBack",
                               "SeparatorFragmentLists"};
  return names[int(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Peelers, PeelDepthFunctionCaseGLTest,
                         ::testing::Values(Peeler::Group, Peeler::Dual, Peeler::FrontToBack,
                                           Peeler::FragmentLists),
                         peelerName);

}  // namespace
}  // namespace ivshadow::test
