// Groups and separators nested inside a group (issue 36): the glass of a group inside a group,
// an instance shared under two parents, a SoPeelingSeparator deep inside separators, and a
// light in a separator after the floor. Each casts or lights as Coin's traversal says, by every
// path: RASTER with a RAYS and a MAP light, TRACER and the reference, against the analytic
// picture (before, the inner group's own passes wrote into the outer group's RAYS capture and
// the floor around a nested group's glass stayed lit; the tracer lit the floor with a light
// that GL only turns on after it).
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/ShadowScene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kSize = 240;  // 100 pixels per unit: the camera's height is 2.4

// A red glass (alpha 0.5) of 0.3 x 0.3 at height 0.5 centred at x = `x`, inside `open` ...
// `close`.
std::string glass(double x, const std::string& open, const std::string& close) {
  std::ostringstream iv;
  iv << open << "\nMaterial { ambientColor 0 0 0 diffuseColor 1 0 0 specularColor 0 0 0 "
     << "transparency 0.5 }\nCoordinate3 { point [ " << x - 0.15 << " -0.15 0.5, " << x + 0.15
     << " -0.15 0.5, " << x + 0.15 << " 0.15 0.5, " << x - 0.15 << " 0.15 0.5 ] }\n"
     << "FaceSet { numVertices 4 }\n"
     << close << "\n";
  return iv.str();
}

// A white floor seen straight down, lit at 45 degrees from +x by `light`: a glass at height
// 0.5 shadows the floor 0.5 towards -x of it, beside it.
std::string scene(const std::string& light, const std::string& content, const char* renderer) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
     << "TransparentShadowGroup { renderer " << renderer << "\n"
     << light << "\n"
     << "Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
     << "Coordinate3 { point [ -1.2 -1.2 0, 1.2 -1.2 0, 1.2 1.2 0, -1.2 1.2 0 ] }\n"
     << "FaceSet { numVertices 4 }\n"
     << content << "}\n}\n";
  return iv.str();
}

std::string light(const char* method) {
  return std::string("DeepShadowDirectionalLight { direction -1 0 -1 method ") + method + " }";
}

const double kLit = 255.0 * std::sqrt(0.5);  // Lambert's cos 45 of white
const std::array<double, 3> kShadow = transmittance(kRedGlass, ColourModel::Saturate);

struct Path {
  const char* name;
  const char* method;
  const char* renderer;  // "" : the reference
};

class NestedGroups : public ::testing::TestWithParam<Path> {
 protected:
  Image render(const std::string& content, const std::string& lights = "") {
    init();
    const Path path = GetParam();
    const std::string text = scene(lights.empty() ? light(path.method) : lights, content,
                                   *path.renderer == '\0' ? "RASTER" : path.renderer);
    return *path.renderer == '\0' ? referenceIv(text, kSize) : renderIv(text, kSize);
  }

  // The floor at x (y = 0): lit, or in the shadow of a glass. 15 pixels from every edge: one
  // 8-bit step of rounding and one more for the map's filtering of a flat receiver.
  static void expectFloor(const Image& image, double x, bool shadowed, const char* what) {
    const std::uint8_t* pixel = image.pixel(int(std::lround(120 + 100 * x)), 120);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(pixel[c], kLit * (shadowed ? kShadow[std::size_t(c)] : 1.0), 2.0)
          << what << " at x = " << x << ", channel " << c;
  }
};

TEST_P(NestedGroups, AGlassInAGroupInsideTheGroupCastsOnItsFloor) {
  const Image image = render(glass(0.35, "TransparentShadowGroup {", "}"));
  expectFloor(image, -0.15, true, "the shadow");
  expectFloor(image, -0.8, false, "the lit floor");
}

// Straight down, the nested glass shadows the floor under itself: seen through the glass,
// half the glass's own red (lit fully) and half the shadowed floor. There the inner group's
// own passes had overwritten the outer group's RAYS capture, and the floor stayed lit.
TEST_P(NestedGroups, AGlassInAGroupInsideTheGroupShadowsTheFloorUnderIt) {
  const Image image = render(glass(0.35, "TransparentShadowGroup {", "}"),
                             std::string("DeepShadowDirectionalLight { direction 0 0 -1 method ") +
                                 GetParam().method + " }");
  const std::uint8_t* pixel = image.pixel(155, 120);
  for (int c = 0; c < 3; ++c)
    // Two 8-bit steps: the glass's and the floor's rounding, and the blend's.
    EXPECT_NEAR(pixel[c], 255.0 * (0.5 * (c == 0 ? 1.0 : 0.0) + 0.5 * kShadow[std::size_t(c)]), 2.5)
        << "channel " << c;
}

TEST_P(NestedGroups, AnInstanceSharedUnderTwoParentsCastsTwice) {
  const Image image = render(
      glass(0.0, "Separator { Translation { translation -0.2 0 0 } DEF Shared Separator {", "} }") +
      "Separator { Translation { translation 0.55 0 0 } USE Shared }\n");
  expectFloor(image, -0.7, true, "the first instance's shadow");
  expectFloor(image, 0.05, true, "the second instance's shadow");
  expectFloor(image, -0.45, false, "the floor between the first shadow and its glass");
}

TEST_P(NestedGroups, APeelingSeparatorDeepInsideTheGroupCasts) {
  const Image image = render(glass(0.35, "Separator { Separator { PeelingSeparator {", "} } }"));
  expectFloor(image, -0.15, true, "the shadow");
  expectFloor(image, -0.8, false, "the lit floor");
}

// GL turns a light on where it is traversed, until its separator ends: a light in a separator
// after the floor does not light it (in Coin, and so in every path).
TEST_P(NestedGroups, ALightInASeparatorAfterTheFloorDoesNotLightIt) {
  const Image image =
      render(glass(0.35, "", "") + "Separator { DirectionalLight { direction 0 0 -1 } }\n",
             light(GetParam().method));
  expectFloor(image, -0.15, true, "the shadow");
  expectFloor(image, -0.8, false, "the lit floor");
}

INSTANTIATE_TEST_SUITE_P(
    Paths, NestedGroups,
    ::testing::Values(Path{"RasterRays", "RAYS", "RASTER"}, Path{"RasterMap", "MAP", "RASTER"},
                      Path{"Tracer", "RAYS", "TRACER"}, Path{"Reference", "RAYS", ""}),
    [](const ::testing::TestParamInfo<Path>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ivshadow::test

namespace ivshadow::test {
namespace {

// The same inside a SoPeelingSeparator outside any group, drawn in several peel passes: the
// light met in one pass stayed set for the next, lighting the glass traversed before it (the
// differential test found it in groups first). Coin lights the first glass with the first
// light only; GL and the reference must agree, to an 8-bit step and the peel's blend.
TEST(NestedGroupsPeeling, ALightInAPeelingSeparatorLightsOnlyWhatFollowsItInEveryPass) {
  init();
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
      "DirectionalLight { direction 0 0 -1 intensity 0.3 }\n"
      "PeelingSeparator { method FRAGMENT_LISTS\n"
      "  Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 "
      "transparency 0.5 }\n"
      "  Coordinate3 { point [ -1 -0.5 0, 0 -0.5 0, 0 0.5 0, -1 0.5 0 ] }\n"
      "  FaceSet { numVertices 4 }\n"
      "  DirectionalLight { direction 0 0 -1 intensity 0.6 }\n"
      "  Coordinate3 { point [ 0 -0.5 0.1, 1 -0.5 0.1, 1 0.5 0.1, 0 0.5 0.1 ] }\n"
      "  FaceSet { numVertices 4 }\n"
      "}\n}\n";
  const Image gl = renderIv(text, kSize);
  const Image exact = referenceIv(text, kSize);
  // The first glass: 0.3 of white through alpha 0.5 over black; the second: 0.9.
  for (const auto& [x, expected] : {std::pair{60, 0.5 * 0.3}, std::pair{180, 0.5 * 0.9}}) {
    EXPECT_NEAR(exact.pixel(x, 120)[0], 255.0 * expected, 1.0) << x;
    EXPECT_NEAR(gl.pixel(x, 120)[0], 255.0 * expected, 2.0) << x;
  }
}

}  // namespace
}  // namespace ivshadow::test

namespace ivshadow::test {
namespace {

// A light in a separator ends with it (Coin turns its GL light off there); the group's program
// adds up GL lights by number and lit the floor after the separator with it under RASTER
// (found in review). Coin, TRACER and the reference light the floor with the outer light only.
TEST(NestedGroupsScope, ALightInASeparatorBeforeTheFloorEndsWithIt) {
  init();
  for (const char* renderer : {"RASTER", "TRACER"}) {
    SCOPED_TRACE(renderer);
    const std::string text =
        std::string("#Inventor V2.1 ascii\nSeparator {\n"
                    "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 "
                    "height 2.4 }\n"
                    "TransparentShadowGroup { renderer ") +
        renderer +
        "\n  DirectionalLight { direction 0 0 -1 intensity 0.3 }\n"
        "  Separator { DirectionalLight { direction 0 0 -1 intensity 0.6 } }\n"
        "  Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
        "  Coordinate3 { point [ -1.2 -1.2 0, 1.2 -1.2 0, 1.2 1.2 0, -1.2 1.2 0 ] }\n"
        "  FaceSet { numVertices 4 }\n}\n}\n";
    const Image image = renderIv(text, kSize);
    // 0.3 of white; one 8-bit step of rounding.
    EXPECT_NEAR(image.pixel(120, 120)[0], 255.0 * 0.3, 1.0);
    EXPECT_NEAR(referenceIv(text, kSize).pixel(120, 120)[0], 255.0 * 0.3, 1.0);
  }
}

}  // namespace
}  // namespace ivshadow::test
