// Issue 38: with the group drawing by GL, selecting one face of a box in FreeCAD turned every
// face of the box green. FreeCAD's SoBrepFaceSet draws the selected face with the selection
// colour as its emissive colour inside a state push, pops, and draws the whole shape again,
// all in one node; Mesa took the material sent back after the pop as a per-vertex attribute
// that the group's programs never read (nodes/MaterialSyncElement.h). FreeCAD's view draws with
// GL_LESS, so the shape drawn again leaves the highlight in front of it; after a RAYS light's
// capture pass Coin's depth element put back LEQUAL, and the shape drawn again covered the
// highlight (nodes/RayMethod.cpp). Here a callback node draws the faces the same way, and two
// sibling separators draw two shapes with materials of their own. The face drawn after the
// emissive one must look as it does when no face is emissive, and the emissive one brighter by
// its emissive colour: both pictures are the group's own, so the expectation does not depend
// on how the group lights a face.
#include <epoxy/gl.h>

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/CoinRef.h"
#include "tests/gl/FreeCadViewRoot.h"
#include "tests/gl/GlContextTest.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoLazyElement.h>
#include <Inventor/elements/SoTextureEnabledElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <array>
#include <ostream>
#include <string>

namespace ivshadow::test {
namespace {

class ShapeMaterialGLTest : public GlContextTest {};

// FreeCAD's selection green (SelectionColor 0x1CAD1C).
const SbColor kGreen(28 / 255.0f, 173 / 255.0f, 28 / 255.0f);

enum class Pattern {
  OneShape,  // one node: push, emissive, texture off, the left face, pop, both faces
  Siblings,  // Separator { Material { emissiveColor } left face } right face
};

// The two faces, each a quad of four vertices: few enough that Mesa keeps the left one's
// vertices buffered when the right one's material is sent (gl/CurrentMaterial.h, and more
// than eight buffered would make it take the material as current by itself).
struct Faces {
  CoinRef<SoIndexedFaceSet> left;
  CoinRef<SoIndexedFaceSet> right;
  CoinRef<SoIndexedFaceSet> whole;  // both
  SbColor emissive;
};

SoIndexedFaceSet* quad(int first) {
  auto* face = new SoIndexedFaceSet;
  const int32_t indices[] = {first, first + 1, first + 2, first + 3, -1};
  face->coordIndex.setValues(0, 5, indices);
  return face;
}

// As FreeCAD's SoBrepFaceSet::renderSelection followed by the whole shape.
SoCallback* selectedFaceShape(Faces& faces) {
  auto* callback = new SoCallback;
  callback->setCallback(
      [](void* data, SoAction* action) {
        if (!action->isOfType(SoGLRenderAction::getClassTypeId())) return;
        auto* drawn = static_cast<Faces*>(data);
        auto* render = static_cast<SoGLRenderAction*>(action);
        SoState* state = action->getState();
        state->push();
        SoLazyElement::setEmissive(state, &drawn->emissive);
        SoTextureEnabledElement::set(state, nullptr, false);
        drawn->left->GLRender(render);
        state->pop();
        drawn->whole->GLRender(render);
      },
      &faces);
  return callback;
}

// A 2 x 2 view of two grey faces side by side, lit by a deep shadow light of `method` above
// them, in a group drawing by GL.
CoinRef<SoSeparator> scene(Pattern pattern, const char* method, Faces& faces) {
  CoinRef<SoSeparator> root = freeCadViewRoot();
  auto* group = new SoTransparentShadowGroup;
  group->renderer = SoTransparentShadowGroup::RASTER;
  auto* light = new SoDeepShadowLight;
  light->location.setValue(0, 0, 3);
  light->method.set(method);
  group->addChild(light);
  auto* material = new SoMaterial;
  material->diffuseColor.setValue(0.5f, 0.5f, 0.5f);
  group->addChild(material);
  auto* coordinates = new SoCoordinate3;
  const SbVec3f points[] = {{-1, -1, 0},      {0, -1, 0},          {0, 1, 0},        {-1, 1, 0},
                            {0, -1, 0},       {1, -1, 0},          {1, 1, 0},        {0, 1, 0},
                            {-1, 0.9f, 0.1f}, {-0.9f, 0.9f, 0.1f}, {-0.9f, 1, 0.1f}, {-1, 1, 0.1f}};
  coordinates->point.setValues(0, 12, points);
  group->addChild(coordinates);
  // A shape drawn just before, as FreeCAD's other shapes are: its four vertices are still
  // buffered when the emissive colour is set.
  group->addChild(quad(8));
  faces.left = CoinRef<SoIndexedFaceSet>(quad(0));
  faces.right = CoinRef<SoIndexedFaceSet>(quad(4));
  faces.whole = CoinRef<SoIndexedFaceSet>(quad(0));
  const int32_t both[] = {0, 1, 2, 3, -1, 4, 5, 6, 7, -1};
  faces.whole->coordIndex.setValues(0, 10, both);
  if (pattern == Pattern::OneShape) {
    group->addChild(selectedFaceShape(faces));
  } else {
    auto* selected = new SoSeparator;
    auto* emissive = new SoMaterial;
    emissive->emissiveColor.setValue(faces.emissive);
    selected->addChild(emissive);
    selected->addChild(faces.left.get());
    group->addChild(selected);
    group->addChild(faces.right.get());
  }
  root->addChild(group);
  return root;
}

struct Case {
  Pattern pattern;
  const char* method;
};

void PrintTo(const Case& c, std::ostream* out) {
  *out << (c.pattern == Pattern::OneShape ? "one shape" : "sibling shapes") << ", " << c.method;
}

class ShapeMaterialCaseGLTest : public ShapeMaterialGLTest,
                                public ::testing::WithParamInterface<Case> {};

std::array<int, 3> rgb(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

TEST_P(ShapeMaterialCaseGLTest, TheFaceAfterAnEmissiveOneKeepsItsOwnMaterial) {
  const Case c = GetParam();
  Image pictures[2];
  for (int emissive = 0; emissive < 2; ++emissive) {
    Faces faces;
    faces.emissive = emissive == 1 ? kGreen : SbColor(0, 0, 0);
    CoinRef<SoSeparator> root = scene(c.pattern, c.method, faces);
    renderer().render(root.get());
    pictures[emissive] = renderer().read();
  }
  const Image& plain = pictures[0];
  const Image& selected = pictures[1];
  const int y = plain.height() / 2;
  // The middle of each face, away from the seam between them.
  const int leftX = plain.width() / 4;
  const int rightX = 3 * plain.width() / 4;
  const std::array<int, 3> right = rgb(selected, rightX, y);
  const std::array<int, 3> rightPlain = rgb(plain, rightX, y);
  const std::array<int, 3> left = rgb(selected, leftX, y);
  const std::array<int, 3> leftPlain = rgb(plain, leftX, y);
  for (int channel = 0; channel < 3; ++channel) {
    SCOPED_TRACE("channel " + std::to_string(channel));
    // The same program, the same light and the same face: the same value.
    EXPECT_EQ(right[std::size_t(channel)], rightPlain[std::size_t(channel)]) << "right face";
    // The emissive colour is added before the sum is clamped to 1; one 8-bit step for the
    // rounding of the colour and of the sum.
    const int expected =
        std::min(255, leftPlain[std::size_t(channel)] + int(kGreen[channel] * 255.0f + 0.5f));
    EXPECT_NEAR(left[std::size_t(channel)], expected, 1) << "left face";
  }
}

INSTANTIATE_TEST_SUITE_P(
    PatternsAndMethods, ShapeMaterialCaseGLTest,
    ::testing::Values(Case{Pattern::OneShape, "MAP"}, Case{Pattern::OneShape, "RAYS"},
                      Case{Pattern::Siblings, "MAP"}, Case{Pattern::Siblings, "RAYS"}),
    [](const ::testing::TestParamInfo<Case>& info) {
      return std::string(info.param.pattern == Pattern::OneShape ? "OneShape" : "Siblings") +
             info.param.method;
    });

}  // namespace
}  // namespace ivshadow::test
