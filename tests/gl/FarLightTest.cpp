// A point light far from its casters (issue 36): at 1000 units a glass filled less than a
// texel of the light's cube map and its shadow vanished under MAP and OPACITY_MAP, while RAYS
// kept it; past about 1e5 no map can tell the casters' depths apart in floats; at 2e19 the
// light's distance overflows a float and the group's RASTER picture was black, where plain
// Coin, TRACER and the reference draw the unlit scene. Every method gives the analytic shadow
// (or traces it, saying why), and the overflowing light draws what plain Coin draws.
#include "ivshadow/IvShadowInit.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/ShadowScene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kSize = 240;  // 100 pixels per unit: the camera's height is 2.4

// A white floor seen straight down and a red glass (alpha 0.5) of 0.3 x 0.3 at height 0.5
// around x = 0.35; the light lies `distance` from the glass's centre at 45 degrees towards +x,
// so the glass's shadow falls on x in [-0.3, 0] (in parallel light), beside the glass.
std::string scene(double distance, const std::string& groupFields, bool group = true) {
  const double along = distance / std::sqrt(2.0);
  std::ostringstream iv;
  iv.precision(17);
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
     << (group ? "TransparentShadowGroup { renderer RASTER " + groupFields
               : std::string("Separator {"))
     << "\n"
     << "PointLight { location " << 0.35 + along << " 0 " << 0.5 + along << " }\n"
     << "Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
     << "Coordinate3 { point [ -1.2 -1.2 0, 1.2 -1.2 0, 1.2 1.2 0, -1.2 1.2 0 ] }\n"
     << "FaceSet { numVertices 4 }\n"
     << "Material { diffuseColor 1 0 0 specularColor 0 0 0 transparency 0.5 }\n"
     << "Coordinate3 { point [ 0.2 -0.15 0.5, 0.5 -0.15 0.5, 0.5 0.15 0.5, 0.2 0.15 0.5 ] }\n"
     << "FaceSet { numVertices 4 }\n}\n}\n";
  return iv.str();
}

// The floor at 45 degrees to the light: Lambert's cos 45 of white, and in the shadow the red
// glass's transmittance (ShadowScene.h: red 0.5, green and blue 0.25).
const double kLit = 255.0 * std::sqrt(0.5);
const std::array<double, 3> kShadow = transmittance(kRedGlass, ColourModel::Saturate);

struct Case {
  const char* name;
  const char* fields;  // the group's; "" for the reference
  double distance;
  bool traced;  // a map method that must say it traces instead
};

class FarLight : public ::testing::TestWithParam<Case> {};

TEST_P(FarLight, CastsTheAnalyticShadowOrTracesItSayingWhy) {
  init();
  const Case c = GetParam();
  CoinMessageCapture messages;
  const std::string text = scene(c.distance, c.fields);
  const Image image = *c.fields == '\0' ? referenceIv(text, kSize) : renderIv(text, kSize);
  // 15 pixels inside the shadow's edges and 40 from the glass: one 8-bit step of rounding,
  // and 1.5 more for the light's direction, which changes across the floor by 1.2 / distance
  // (a thousandth at 1000 units) and for the map's filtering of a flat receiver.
  const std::uint8_t* shadowed = image.pixel(105, 120);
  const std::uint8_t* lit = image.pixel(40, 120);
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_NEAR(shadowed[channel], kLit * kShadow[std::size_t(channel)], 2.5) << channel;
    EXPECT_NEAR(lit[channel], kLit, 2.5) << channel;
  }
  bool said = false;
  for (const CoinMessageCapture::Message& m : messages.messages())
    said = said || m.text.find("it traces shadow rays instead") != std::string::npos;
  EXPECT_EQ(said, c.traced);
}

INSTANTIATE_TEST_SUITE_P(Methods, FarLight,
                         ::testing::Values(Case{"Map1e3", "method MAP", 1e3, false},
                                           Case{"OpacityMap1e3", "method OPACITY_MAP", 1e3, false},
                                           Case{"Map1e6", "method MAP", 1e6, true},
                                           Case{"OpacityMap1e18", "method OPACITY_MAP", 1e18, true},
                                           Case{"Rays1e18", "method RAYS", 1e18, false},
                                           Case{"Volumes1e3", "method VOLUMES", 1e3, false},
                                           Case{"Tracer1e18", "renderer TRACER", 1e18, false},
                                           Case{"Reference1e18", "", 1e18, false}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name);
                         });

// Past float's range the light reaches nothing in plain Coin (its fixed-function GL) and in
// the tracer; the group's shading made the whole picture NaN, black. It draws what plain Coin
// draws: the glass's ambient over an unlit floor.
TEST(FarLightOverflow, TheGroupDrawsWhatPlainCoinDraws) {
  const Image coin = renderIv(scene(2e19, "", false), kSize);
  for (const char* fields : {"renderer RASTER", "renderer TRACER"}) {
    SCOPED_TRACE(fields);
    const Image group = renderIv(scene(2e19, fields), kSize);
    for (const auto& [x, y] : {std::pair{105, 120}, std::pair{40, 120}, std::pair{155, 120}})
      for (int channel = 0; channel < 3; ++channel)
        // Coin lights per vertex, the group per pixel: equal here, where no light arrives;
        // one 8-bit step of rounding.
        EXPECT_NEAR(group.pixel(x, y)[channel], coin.pixel(x, y)[channel], 1.0)
            << x << ',' << y << ' ' << channel;
  }
  // The glass is not black in Coin's picture (ambient 0.2 x 0.2 through alpha 0.5): the
  // comparison above can tell a black picture from it.
  EXPECT_GT(coin.pixel(155, 120)[0], 0);
}

}  // namespace
}  // namespace ivshadow::test
