// How a deep shadow map is looked up at receivers that stress its bias: a light low over the
// floor, grazing it, and an opaque wall standing on that floor. Pictures computed in the test
// (Lambert under a point light, the shadow from similar triangles), with MAP at its default
// bias and with each filter width.
#include "tests/gl/ShadowScene.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace ivshadow::test {
namespace {

// The floor [-1, 1]^2 at z = 0, seen from above: 100 pixels a unit (ShadowScene's camera).
constexpr double kPixel = 0.01;
// Whole 8-bit steps: the map's lookup adds no error away from edges.
constexpr double kTolerance = 1.0;

struct Lookup {
  const char* name;
  const char* fields;  // the light's filter fields
  int width;           // texels the filter spans (0: the nearest texel)
};

class MapLookup : public ::testing::TestWithParam<Lookup> {};

std::string scene(const std::string& light, const std::string& casters) {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
         "  TransparentShadowGroup { renderer RASTER\n" +
         light +
         "\n    Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
         "    Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }\n"
         "    QuadMesh { verticesPerRow 2 verticesPerColumn 2 }\n" +
         casters + "\n  }\n}\n";
}

// Lambert at the floor point (x, y) under a point light at (lx, 0, lz) of intensity 1: the
// light's height over its distance (Coin's point light has no attenuation by default).
double lambert(double x, double y, double lx, double lz) {
  const double dx = x - lx;
  return 255.0 * lz / std::sqrt(dx * dx + y * y + lz * lz);
}

// A light 0.3 over the floor, 3 units beside it: the floor is lit at 84 to 86 degrees from its
// normal, so a texel spans 10 to 15 times its width in depth. Nothing casts onto it; it must
// not shadow itself anywhere (with a depth bias scaled by the slope and capped at ten, its far
// side did).
TEST_P(MapLookup, AGrazingLightLeavesTheFloorLit) {
  const std::string light =
      std::string("    DeepShadowLight { method MAP location -3 0 0.3 ") + GetParam().fields + " }";
  const Image image = renderIv(scene(light, ""), ShadowScene::kSize);
  const auto expected = [](int px, int py) {
    const double x = -1.2 + (px + 0.5) * kPixel, y = 1.2 - (py + 0.5) * kPixel;
    Expectation e;
    const double extent = std::max(std::abs(x), std::abs(y));
    if (std::abs(extent - 1.0) < 2.0 * kPixel) return e;  // the floor's rim
    e.checked = true;
    if (extent < 1.0)
      e.rgb.fill(lambert(x, y, -3.0, 0.3));
    else
      e.rgb.fill(0.0);
    return e;
  };
  const std::string failure = compareWithExpectation(image, expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// An opaque wall standing on the floor along x = 0 (0.5 high, the floor's depth), lit from
// (-3, 0, 0.6): the light clears its top only beyond x = 15, so everything past the wall is
// black right up to it. A depth bias growing with the receiver's slope let the light through
// under the wall: a lit strip along its foot as wide as the bias, 6 texels (0.28 at 128
// texels a face), is long along the grazing ray.
TEST_P(MapLookup, AWallOnTheFloorLetsNoLightThroughItsFoot) {
  const std::string light =
      std::string("    DeepShadowLight { method MAP location -3 0 0.6 resolution 128 ") +
      GetParam().fields + " }";
  const Image image = renderIv(scene(light,
                                     "    Coordinate3 { point [ 0 -1 0, 0 1 0, 0 1 0.5, "
                                     "0 -1 0.5 ] }\n"
                                     "    FaceSet { numVertices 4 }"),
                               ShadowScene::kSize);
  // Either side of the wall's foot the map answers for the texels the lookup reads: half a
  // texel for the nearest, half the filter's width more for PCF, each texel 2 * 3 / 128 wide
  // at the wall (a cube face spans 90 degrees) and stretched on the floor by the light's
  // slope there, 3 / 0.6; plus two pixels for the wall's own line.
  const double reach = 0.5 * (GetParam().width + 1.0) * (6.0 / 128.0) * 5.0 + 2.0 * kPixel;
  const auto expected = [reach](int px, int py) {
    const double x = -1.2 + (px + 0.5) * kPixel, y = 1.2 - (py + 0.5) * kPixel;
    Expectation e;
    const double extent = std::max(std::abs(x), std::abs(y));
    if (std::abs(extent - 1.0) < 2.0 * kPixel) return e;  // the floor's rim
    if (std::abs(x) < reach) return e;                    // the wall's foot, seen edge-on
    e.checked = true;
    if (extent < 1.0 && x < 0.0)
      e.rgb.fill(lambert(x, y, -3.0, 0.6));
    else
      e.rgb.fill(0.0);
    return e;
  };
  const std::string failure = compareWithExpectation(image, expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

INSTANTIATE_TEST_SUITE_P(Filters, MapLookup,
                         ::testing::Values(Lookup{"Nearest", "filter NONE", 0},
                                           Lookup{"Bilinear", "filter PCF filterSize 1", 1},
                                           Lookup{"Pcf3", "filter PCF filterSize 3", 3}),
                         [](const ::testing::TestParamInfo<Lookup>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace ivshadow::test
