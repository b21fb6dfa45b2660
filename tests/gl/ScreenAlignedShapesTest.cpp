// Text2, Image and markers inside a group or a peeling separator drawn by GL are drawn as plain
// Coin draws them (nodes/ScreenAlignedShapes): the expectation is the same scene with the group
// inactive, or a plain Separator, which is plain Coin's picture of them.
#include "tests/gl/ShadowScene.h"

#include <Inventor/SoType.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoText2.h>

#include <gtest/gtest.h>

#include <string>

namespace ivshadow::test {
namespace {

constexpr int kSize = 160;

// A grey floor lit by a deep shadow light of method `method`, with a red label, a green image
// and blue markers over it, inside `open` ... } (a group or a separator).
std::string scene(const std::string& open, const std::string& method) {
  return "#Inventor V2.1 ascii\n"
         "Separator {\n"
         "  OrthographicCamera { position 0 0 5 height 2.4 nearDistance 1 farDistance 10 }\n"
         "  DirectionalLight { direction 0 0 -1 }\n" +
         open + "\n    DeepShadowLight { location 0 0 3 method " + method +
         " }\n"
         "    Material { diffuseColor 0.5 0.5 0.5 }\n"
         "    Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n"
         "    FaceSet { numVertices 4 }\n"
         "    Separator { LightModel { model BASE_COLOR } BaseColor { rgb 1 0 0 }\n"
         "      Translation { translation -0.8 0.5 0.5 } Text2 { string \"WWWW\" } }\n"
         "    Separator { Translation { translation -0.5 -0.6 0.5 }\n"
         "      Image { width 12 height 12 image 1 1 3 0x00FF00 } }\n"
         "    Separator { LightModel { model BASE_COLOR } BaseColor { rgb 0 0 1 }\n"
         "      Coordinate3 { point [ 0.5 -0.5 0.5, 0.7 -0.5 0.5 ] }\n"
         "      MarkerSet { markerIndex [ 11, 11 ] } }\n"
         "  }\n"
         "}\n";
}

// A pixel of one pure colour (the label's red, the image's green, the markers' blue).
bool pure(const std::uint8_t* p) {
  const int high = (p[0] > 200) + (p[1] > 200) + (p[2] > 200);
  const int low = (p[0] < 30) + (p[1] < 30) + (p[2] < 30);
  return high == 1 && low == 2;
}

struct Case {
  const char* name;
  const char* method;  // the light's
  const char* open;    // the group or separator, with its fields
  const char* plain;   // the same, drawn by plain Coin
};

class ScreenAligned : public ::testing::TestWithParam<Case> {};

TEST_P(ScreenAligned, AreDrawnAsPlainCoinDrawsThem) {
  const Image plain = renderIv(scene(GetParam().plain, GetParam().method), kSize);
  const Image drawn = renderIv(scene(GetParam().open, GetParam().method), kSize);
  // Where plain Coin drew a label, image or marker pixel, the group draws that pixel exactly:
  // both draw it with fixed-function GL from the same state.
  int shown = 0, differing = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::uint8_t* p = plain.pixel(x, y);
      if (!pure(p)) continue;
      ++shown;
      const std::uint8_t* q = drawn.pixel(x, y);
      differing += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
    }
  ASSERT_GT(shown, 40) << "the label, image and markers show in plain Coin's picture";
  EXPECT_EQ(differing, 0) << "of " << shown << " pixels";
}

// The group's passes: its camera pass (peeled, or blended as Coin blends), the RAYS capture and
// the map's build; a peeling separator's opaque pass and peels.
const Case kCases[] = {
    {"group_map", "MAP", "TransparentShadowGroup { renderer RASTER",
     "TransparentShadowGroup { isActive FALSE"},
    {"group_coin_blending", "MAP",
     "TransparentShadowGroup { renderer RASTER transparency COIN_BLENDING",
     "TransparentShadowGroup { isActive FALSE"},
    {"group_rays", "RAYS", "TransparentShadowGroup { renderer RASTER",
     "TransparentShadowGroup { isActive FALSE"},
    {"separator_front_to_back", "MAP", "PeelingSeparator { method FRONT_TO_BACK", "Separator {"},
};

INSTANTIATE_TEST_SUITE_P(Cases, ScreenAligned, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name);
                         });

// What files read is Coin's type to the rest of Coin: it writes back as Text2.
TEST(ScreenAlignedShapes, ReadTextIsCoinsText2) {
  SoSeparator* root = readIv("#Inventor V2.1 ascii\nSeparator { Text2 { string \"a\" } }\n");
  SoNode* text = root->getChild(0);
  EXPECT_EQ(text->getTypeId(), SoText2::getClassTypeId());
  EXPECT_STREQ(text->getTypeId().getName().getString(), "Text2");
  root->unref();
}

}  // namespace
}  // namespace ivshadow::test
