// Ordinary Inventor lights inside a shadow group cast: a PointLight, a SpotLight (inside, at
// the edge of and outside its cone, with and without dropOffRate) and a DirectionalLight at an
// oblique angle, each by the map (MAP), the traced rays (RAYS), the shadow volumes (VOLUMES),
// the opacity map (OPACITY_MAP) and the CPU reference, against pictures computed here from the
// geometry alone.
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace ivshadow::test {
namespace {

// ShadowScene's set-up (a 2 x 2 white floor at z = 0 seen straight down, 100 pixels per unit
// at 240 x 240, no ambient, no specular) with `lights` in place of its deep shadow light and a
// red glass of half size `halfSize` at height 0.5, and `more` inside the group after them.
std::string sceneWith(const std::string& lights, const std::string& groupFields, double halfSize,
                      const std::string& more = "") {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
     << "  TransparentShadowGroup { renderer RASTER\n    " << groupFields << "\n    " << lights
     << "\n"
     << "    Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
     << "    Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }\n"
     << "    QuadMesh { verticesPerRow 2 verticesPerColumn 2 }\n"
     << "    Material { ambientColor 0 0 0 specularColor 0 0 0 diffuseColor 1 0 0"
     << " transparency 0.5 }\n"
     << "    Coordinate3 { point [ " << -halfSize << ' ' << -halfSize << " 0.5, " << halfSize << ' '
     << -halfSize << " 0.5, " << halfSize << ' ' << halfSize << " 0.5, " << -halfSize << ' '
     << halfSize << " 0.5 ] }\n"
     << "    FaceSet { numVertices 4 }\n    " << more << "\n  }\n}\n";
  return iv.str();
}

// The red glass (alpha 0.5) by eq. 5.3: red passes 0.5, green and blue 0.25 (ShadowScene.h).
const std::array<double, 3> kRedShadow = transmittance(kRedGlass, ColourModel::Saturate);

// One light's analytic contribution at floor point (x, y): its Lambert term times the
// transmittance where the glass is between the point and the light, or nothing to check
// (a point within `margin` of an edge where the picture jumps: the glass seen from the camera,
// a shadow edge, a cone edge).
struct LightTerm {
  std::function<bool(double x, double y, std::array<double, 3>& rgb)> at;
};

constexpr double kMargin = 0.02;  // two pixels either side of every edge

// A light above the floor's centre at height 1 (point, or spot pointing down): the glass of
// half size s at height 0.5 shadows the floor where max(|x|, |y|) < 2 s.
LightTerm overheadLight(double s, double intensity, double cutOffAngle, double dropOffRate,
                        std::array<double, 3> shadow = kRedShadow) {
  return {[=](double x, double y, std::array<double, 3>& rgb) {
    const double extent = std::max(std::abs(x), std::abs(y));
    if (std::abs(extent - 2.0 * s) < kMargin) return false;
    const double r = std::hypot(x, y);
    const double length = std::sqrt(1.0 + r * r);
    double term = intensity / length;  // Lambert: cos = 1 / length
    if (cutOffAngle > 0.0) {
      // Coin's GL spot: outside the cone nothing, inside cos^(128 dropOffRate) of the angle
      // to the axis, which here is 1 / length as well.
      const double edge = std::tan(cutOffAngle);
      if (std::abs(r - edge) < kMargin) return false;
      term = r > edge ? 0.0 : term * std::pow(1.0 / length, 128.0 * dropOffRate);
    }
    for (int c = 0; c < 3; ++c)
      rgb[std::size_t(c)] += 255.0 * term * (extent < 2.0 * s ? shadow[std::size_t(c)] : 1.0);
    return true;
  }};
}

// A directional light along (dx, 0, -1): Lambert's cosine 1 / sqrt(1 + dx^2) everywhere, and
// the glass's shadow is its square moved by dx * 0.5 along x (similar triangles).
LightTerm obliqueLight(double s, double intensity, double dx,
                       std::array<double, 3> shadow = kRedShadow) {
  return {[=](double x, double y, std::array<double, 3>& rgb) {
    const double shifted = std::max(std::abs(x - dx * 0.5), std::abs(y));
    if (std::abs(shifted - s) < kMargin) return false;
    const double term = intensity / std::sqrt(1.0 + dx * dx);
    for (int c = 0; c < 3; ++c)
      rgb[std::size_t(c)] += 255.0 * term * (shifted < s ? shadow[std::size_t(c)] : 1.0);
    return true;
  }};
}

// The picture of the floor under `terms`, the glass (half size s) seen from the camera and
// the floor's edge left unchecked.
ExpectedImage pictureOf(double s, const std::vector<LightTerm>& terms) {
  return [=](int px, int py) {
    const double x = -1.2 + (px + 0.5) / 100.0;
    const double y = 1.2 - (py + 0.5) / 100.0;
    const double extent = std::max(std::abs(x), std::abs(y));
    Expectation e;
    if (extent >= 1.0 + kMargin) {
      e.checked = true;  // the black background
      return e;
    }
    if (extent > 1.0 - kMargin || extent < s + kMargin) return e;
    std::array<double, 3> rgb{};
    for (const LightTerm& term : terms)
      if (!term.at(x, y, rgb)) return e;
    e.checked = true;
    for (int c = 0; c < 3; ++c) e.rgb[std::size_t(c)] = std::min(rgb[std::size_t(c)], 255.0);
    return e;
  };
}

// The group lights per pixel in float; the transmittance is stored as a 16-bit float (RAYS) or
// a 32-bit float (MAP) and rounded once to 8 bits: one step bounds it, the 1/255.
constexpr double kTolerance = 1.0;

enum class Method { Map, Rays, Volumes, OpacityMap, Reference };

// The group's fields that choose the method. The opacity map's 32 slices over each light's
// fitted range are 0.02 to 0.05 deep, a tenth of the 0.5 (0.7 along the oblique light) from
// the glass to the floor or less: the floor counts the glass fully, and the picture is exact.
const char* methodFields(Method method) {
  return method == Method::Map          ? "method MAP"
         : method == Method::Volumes    ? "method VOLUMES"
         : method == Method::OpacityMap ? "method OPACITY_MAP slices 32"
                                        : "method RAYS";
}

std::string methodName(const ::testing::TestParamInfo<Method>& info) {
  return info.param == Method::Map          ? "Map"
         : info.param == Method::Rays       ? "Rays"
         : info.param == Method::Volumes    ? "Volumes"
         : info.param == Method::OpacityMap ? "OpacityMap"
                                            : "Reference";
}

class LightTypes : public ::testing::TestWithParam<Method> {
 protected:
  void expectPicture(const std::string& lights, double s, const std::vector<LightTerm>& terms,
                     const std::string& extraGroupFields = "", const std::string& more = "") {
    const std::string fields = std::string(methodFields(GetParam())) + " " + extraGroupFields;
    const std::string text = sceneWith(lights, fields, s, more);
    const Image image = GetParam() == Method::Reference ? referenceIv(text, ShadowScene::kSize)
                                                        : renderIv(text, ShadowScene::kSize);
    const std::string failure = compareWithExpectation(image, pictureOf(s, terms), kTolerance);
    EXPECT_TRUE(failure.empty()) << failure;
  }
};

TEST_P(LightTypes, PointLightCastsAsADeepShadowLight) {
  expectPicture("PointLight { location 0 0 1 }", 0.3, {overheadLight(0.3, 1.0, 0.0, 0.0)});
}

TEST_P(LightTypes, SpotLightCastsInsideItsConeAndLightsNothingOutside) {
  // Cone radius tan(0.5) = 0.55 on the floor; the shadow (half size 0.3) lies inside it, a lit
  // ring around it, darkness outside.
  expectPicture("SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.5 }", 0.15,
                {overheadLight(0.15, 1.0, 0.5, 0.0)});
}

TEST_P(LightTypes, SpotLightsDropOffRateShapesItsLight) {
  expectPicture("SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.7 dropOffRate 0.05 }",
                0.15, {overheadLight(0.15, 1.0, 0.7, 0.05)});
}

TEST_P(LightTypes, SpotConeNarrowerThanTheShadowLeavesNoLitRing) {
  // Cone radius tan(0.2) = 0.2, the shadow's half size 0.6: all the cone's light is filtered.
  expectPicture("SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.2 }", 0.3,
                {overheadLight(0.3, 1.0, 0.2, 0.0)});
}

TEST_P(LightTypes, ObliqueDirectionalLightShiftsAndTintsTheShadow) {
  // Along (1, 0, -1): the shadow is the glass moved 0.5 along x, seen beside the glass.
  expectPicture("DirectionalLight { direction 1 0 -1 }", 0.3, {obliqueLight(0.3, 1.0, 1.0)});
}

TEST_P(LightTypes, PointAndDirectionalLightsInOneGroupAddUp) {
  expectPicture(
      "PointLight { location 0 0 1 intensity 0.5 } "
      "DirectionalLight { direction 1 0 -1 intensity 0.5 }",
      0.3, {overheadLight(0.3, 0.5, 0.0, 0.0), obliqueLight(0.3, 0.5, 1.0)});
}

TEST_P(LightTypes, DeepShadowLightsOnlyLeavesOrdinaryLightsUnshadowed) {
  // castingLights DEEP_SHADOW_LIGHTS: the point light lights the floor under the glass fully.
  expectPicture("PointLight { location 0 0 1 }", 0.3,
                {LightTerm{[](double x, double y, std::array<double, 3>& rgb) {
                  const double term = 255.0 / std::sqrt(1.0 + x * x + y * y);
                  for (double& channel : rgb) channel += term;
                  return true;
                }}},
                "castingLights DEEP_SHADOW_LIGHTS");
}

// Coin's SoShadowSpotLight bounds its map by nearDistance: a glass nearer the light than that
// (0.5 away, nearDistance 0.6) is not in the map and casts nothing, so the floor is lit
// unfiltered inside the cone. The map's own bound: RAYS and the reference trace every caster.
TEST(LightTypesMap, ShadowSpotLightsNearDistanceBoundsTheMap) {
  const std::string text = sceneWith(
      "ShadowSpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.7 nearDistance 0.6 }",
      "method MAP", 0.3);
  const Image image = renderIv(text, ShadowScene::kSize);
  const std::string failure = compareWithExpectation(
      image, pictureOf(0.3, {LightTerm{[](double x, double y, std::array<double, 3>& rgb) {
                         const double r = std::hypot(x, y), edge = std::tan(0.7);
                         if (std::abs(r - edge) < kMargin) return false;
                         const double term = r > edge ? 0.0 : 255.0 / std::sqrt(1.0 + r * r);
                         for (double& channel : rgb) channel += term;
                         return true;
                       }}}),
      kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The glass by eq. 5.1 (shadowColor MONOCHROME): every channel passes 1 - alpha = 0.5.
const std::array<double, 3> kGreyShadow = transmittance(kRedGlass, ColourModel::Monochrome);

TEST_P(LightTypes, GroupFieldsAreTheOrdinaryLightsShadowFields) {
  expectPicture("PointLight { location 0 0 1 }", 0.3,
                {overheadLight(0.3, 1.0, 0.0, 0.0, kGreyShadow)}, "shadowColor MONOCHROME");
}

TEST_P(LightTypes, DeepShadowSpotLightCastsWithItsOwnFields) {
  // Its own shadowColor over the group's (COLORED).
  expectPicture(
      "DeepShadowSpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.5"
      " shadowColor MONOCHROME }",
      0.15, {overheadLight(0.15, 1.0, 0.5, 0.0, kGreyShadow)}, "shadowColor COLORED");
}

TEST_P(LightTypes, DeepShadowDirectionalLightCastsWithItsOwnFields) {
  expectPicture("DeepShadowDirectionalLight { direction 1 0 -1 shadowColor MONOCHROME }", 0.3,
                {obliqueLight(0.3, 1.0, 1.0, kGreyShadow)}, "shadowColor COLORED");
}

// Issue 36: the dedicated spot and directional nodes exist for castingLights
// DEEP_SHADOW_LIGHTS, and cast nothing there on any path (only SoDeepShadowLight was counted).
TEST_P(LightTypes, DeepShadowSpotAndDirectionalLightsCastUnderDeepShadowLightsOnly) {
  expectPicture(
      "DeepShadowSpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.5"
      " shadowColor MONOCHROME }",
      0.15, {overheadLight(0.15, 1.0, 0.5, 0.0, kGreyShadow)},
      "shadowColor COLORED castingLights DEEP_SHADOW_LIGHTS");
  expectPicture("DeepShadowDirectionalLight { direction 1 0 -1 shadowColor MONOCHROME }", 0.3,
                {obliqueLight(0.3, 1.0, 1.0, kGreyShadow)},
                "shadowColor COLORED castingLights DEEP_SHADOW_LIGHTS");
}

TEST_P(LightTypes, SpotConeWiderThanOneFaceCastsAsAPointLight) {
  // cutOffAngle 1.2 (69 degrees, wider than kMaxSpotFaceHalfAngle): the map is a cube; the
  // cone's rim (radius tan(1.2) = 2.6) lies beyond the floor, so all of it is lit.
  expectPicture("SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 1.2 }", 0.3,
                {overheadLight(0.3, 1.0, 1.2, 0.0)});
}

TEST_P(LightTypes, DirectionalLightsMapCoversWhatTheViewShowsOfFarCasters) {
  // A second glass 50 units away makes the casters' bounds 25 times the floor: a map over all
  // of them would put 0.1 units (10 pixels) in a texel and blur the shadow's edges past the
  // test's two-pixel margin.
  // The opacity map's slices divide the casters' whole depth along the light, 36 units here:
  // 32 slices are 1.1 deep, more than the glass's 0.7 above the floor, which then gets part
  // of its absorption only (docs/DEEP_SHADOWS.md, "method OPACITY_MAP"; the partial share is
  // tested in OpacityMap.AReceiverNearerThanASliceGetsThatShareOfTheAbsorption).
  if (GetParam() == Method::OpacityMap) GTEST_SKIP() << "the far glass stretches the slices";
  expectPicture("DirectionalLight { direction 1 0 -1 }", 0.3, {obliqueLight(0.3, 1.0, 1.0)}, "",
                "Translation { translation 50 0 0 } FaceSet { numVertices 4 }");
}

INSTANTIATE_TEST_SUITE_P(Methods, LightTypes,
                         ::testing::Values(Method::Map, Method::Rays, Method::Volumes,
                                           Method::OpacityMap, Method::Reference),
                         methodName);

// The map of each light type: what it is and where its layers are (a one-face map peels face
// 0 only, and with the one glass in front of the floor keeps two layers there).
TEST(LightTypesMap, EachLightTypeHasTheMapItsShapeNeeds) {
  struct Case {
    std::string light, projection;
  };
  for (const Case& c :
       {Case{"PointLight { location 0 0 1 }", "CUBE"},
        Case{"SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 0.7 }", "PERSPECTIVE"},
        Case{"SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 1.2 }", "CUBE"},
        Case{"DirectionalLight { direction 1 0 -1 }", "ORTHOGRAPHIC"}}) {
    SoNode* root = nullptr;
    renderIv(sceneWith(c.light, "method MAP", 0.3), ShadowScene::kSize, &root);
    const DeepShadowStatistics statistics = collectDeepShadowStatistics(root);
    ASSERT_EQ(statistics.lights.size(), 1u) << c.light;
    const DeepShadowLightStatistics& light = statistics.lights[0];
    EXPECT_EQ(light.method, "MAP") << c.light;
    EXPECT_EQ(light.projection, c.projection) << c.light;
    if (c.projection != "CUBE") {
      // The glass (a layer that lets light through), then the floor (opaque) behind it.
      EXPECT_EQ(light.layersUsed[0], 2) << c.light;
      for (std::size_t face = 1; face < 6; ++face) EXPECT_EQ(light.layersUsed[face], 0) << c.light;
    }
    root->unref();
  }
}

// A DeepShadowDirectionalLight's own map fields over the group's.
TEST(LightTypesMap, DeepShadowDirectionalLightsOwnMapFieldsWin) {
  SoNode* root = nullptr;
  renderIv(sceneWith("DeepShadowDirectionalLight { direction 1 0 -1 method MAP resolution 256 }",
                     "method RAYS resolution 1024", 0.3),
           ShadowScene::kSize, &root);
  const DeepShadowStatistics statistics = collectDeepShadowStatistics(root);
  ASSERT_EQ(statistics.lights.size(), 1u);
  EXPECT_EQ(statistics.lights[0].method, "MAP");
  EXPECT_EQ(statistics.lights[0].resolution, 256);
  EXPECT_EQ(statistics.lights[0].projection, "ORTHOGRAPHIC");
  root->unref();
}

// Light along (1, 0, -1)/sqrt(2), casters from x = -1 to 50.3: across the light (the plane
// normal to it) the casters span x' = (x + z)/sqrt(2) in [-0.71, 35.9] and y in [-1, 1]. The
// orthographic camera's box (x, y in [-1.2, 1.2], z from 4 down to -5) projects to x' in
// [-4.38, 3.68], y in [-1.2, 1.2]. What the map must cover is the overlap, 4.38 by 2; it may
// add a margin for a moving camera, but not the casters' 36.6 along x'.
TEST(LightTypesMap, DirectionalMapIsTheCastersClippedToTheView) {
  SoNode* root = nullptr;
  renderIv(sceneWith("DirectionalLight { direction 1 0 -1 }", "method MAP", 0.3,
                     "Translation { translation 50 0 0 } FaceSet { numVertices 4 }"),
           ShadowScene::kSize, &root);
  const DeepShadowStatistics statistics = collectDeepShadowStatistics(root);
  ASSERT_EQ(statistics.lights.size(), 1u);
  const std::array<float, 2> extent = statistics.lights[0].extent;
  const float across = std::max(extent[0], extent[1]), along = std::min(extent[0], extent[1]);
  EXPECT_GE(across, 4.38f - 0.01f);  // the overlap, to rounding
  EXPECT_LE(across, 2.0f * 4.38f);
  EXPECT_NEAR(along, 2.0f, 0.01f);  // y: the casters' own 2, within the view's 2.4
  root->unref();
}

// The directional scene of sceneWith, and a copy of its floor and glass 30 units along x: a
// second floor that a map fitted to the first view does not cover.
std::string twoFloorScene() {
  return sceneWith(
      "DirectionalLight { direction 1 0 -1 }", "method MAP", 0.3,
      "Translation { translation 30 0 0 }"
      " Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }"
      " Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }"
      " QuadMesh { verticesPerRow 2 verticesPerColumn 2 }"
      " Material { ambientColor 0 0 0 specularColor 0 0 0 diffuseColor 1 0 0"
      " transparency 0.5 }"
      " Coordinate3 { point [ -0.3 -0.3 0.5, 0.3 -0.3 0.5, 0.3 0.3 0.5, -0.3 0.3 0.5 ] }"
      " FaceSet { numVertices 4 }");
}

// The camera moves from the first floor to a second one 30 units along x: the directional
// light's map, fitted to the first view, does not cover the second, and is fitted again; the
// second picture is the same analytic one. A third frame from the same place builds nothing.
TEST(LightTypesMap, DirectionalMapFollowsTheCameraToCastersItDidNotCover) {
  const std::string text = twoFloorScene();
  SoSeparator* root = readIv(text);
  std::string error;
  auto renderer = CheckedRenderer::create(ShadowScene::kSize, ShadowScene::kSize, error);
  ASSERT_TRUE(renderer) << error;
  const ExpectedImage expected = pictureOf(0.3, {obliqueLight(0.3, 1.0, 1.0)});
  renderer->render(root);
  std::string failure = compareWithExpectation(renderer->read(), expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << "first floor: " << failure;
  const int before = collectDeepShadowStatistics(root).rebuilds;

  SoCamera* camera = nullptr;
  for (int i = 0; i < root->getNumChildren() && camera == nullptr; ++i)
    if (root->getChild(i)->isOfType(SoCamera::getClassTypeId()))
      camera = static_cast<SoCamera*>(root->getChild(i));
  ASSERT_NE(camera, nullptr);
  camera->position.setValue(30.0f, 0.0f, 5.0f);
  renderer->render(root);
  failure = compareWithExpectation(renderer->read(), expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << "second floor, 30 units along x: " << failure;
  const int after = collectDeepShadowStatistics(root).rebuilds;
  EXPECT_EQ(after, before + 1);

  renderer->render(root);
  EXPECT_EQ(collectDeepShadowStatistics(root).rebuilds, after);
  root->unref();
}

// The file's own camera inside the group (as when a file is wrapped in a group unchanged),
// looking at the second floor 30 units along x: the directional map is fitted to that camera,
// traversed after the maps are built, not to the view volume in force where the group
// begins (here Coin's default, a 2-unit box at the origin, which shows no caster of that floor).
TEST(LightTypesMap, DirectionalMapFollowsACameraInsideTheGroup) {
  std::string text = twoFloorScene();
  const std::string camera =
      "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }";
  const std::size_t at = text.find(camera);
  ASSERT_NE(at, std::string::npos);
  text.erase(at, camera.size());
  // After the group's fields, before its first child.
  text.insert(text.find("DirectionalLight {"),
              "OrthographicCamera { position 30 0 5 nearDistance 1 farDistance 10 height 2.4 } ");
  const Image image = renderIv(text, ShadowScene::kSize);
  const std::string failure =
      compareWithExpectation(image, pictureOf(0.3, {obliqueLight(0.3, 1.0, 1.0)}), kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// A point light beside the corner of the casters' box: (1.3, 1.3, 0.8) against the box
// [-1, 1]^2 x [0, 0.5], 0.52 from it but only 0.3 from it along each axis. A red glass fills
// that corner (x, y in [0.6, 1] at height 0.5). A cube face clips by depth along its axis,
// so the map's near plane must be below 0.3; at 0.99 of the distance (0.51) the part of the
// glass within 0.51 along every axis (x, y above 0.79) was cut out of the map and its shadow
// (on the floor for x, y above -0.07) was missing. The shadow: the glass scaled by 0.8 / 0.3
// about the light's foot, x, y in [-0.567, 0.5].
TEST(LightTypesMap, APointLightBesideTheCastersCornerKeepsTheCornerInItsMap) {
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
      "  TransparentShadowGroup { renderer RASTER method MAP\n"
      "    PointLight { location 1.3 1.3 0.8 }\n"
      "    Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
      "    Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }\n"
      "    QuadMesh { verticesPerRow 2 verticesPerColumn 2 }\n"
      "    Material { ambientColor 0 0 0 specularColor 0 0 0 diffuseColor 1 0 0"
      " transparency 0.5 }\n"
      "    Coordinate3 { point [ 0.6 0.6 0.5, 1 0.6 0.5, 1 1 0.5, 0.6 1 0.5 ] }\n"
      "    FaceSet { numVertices 4 }\n  }\n}\n";
  const Image image = renderIv(text, ShadowScene::kSize);
  const auto expected = [](int px, int py) {
    const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
    Expectation e;
    const double extent = std::max(std::abs(x), std::abs(y));
    if (extent >= 1.0 + kMargin) {
      e.checked = true;  // the black background
      return e;
    }
    if (extent > 1.0 - kMargin) return e;
    // The glass seen from the camera, and the shadow's edges.
    if (std::min(x, y) > 0.6 - kMargin) return e;
    const double low = 1.3 - 0.7 * 0.8 / 0.3, high = 1.3 - 0.3 * 0.8 / 0.3;
    const bool xIn = x > low && x<high, yIn = y> low && y < high;
    if ((std::abs(x - low) < kMargin || std::abs(x - high) < kMargin) && yIn) return e;
    if ((std::abs(y - low) < kMargin || std::abs(y - high) < kMargin) && xIn) return e;
    const double dx = x - 1.3, dy = y - 1.3;
    const double term = 255.0 * 0.8 / std::sqrt(dx * dx + dy * dy + 0.64);  // Lambert
    e.checked = true;
    for (int c = 0; c < 3; ++c)
      e.rgb[std::size_t(c)] = term * (xIn && yIn ? kRedShadow[std::size_t(c)] : 1.0);
    return e;
  };
  const std::string failure = compareWithExpectation(image, expected, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// Lights that cannot cast light without a shadow, with one warning naming them; the picture is
// still drawn (the floor fully lit by the other light).
TEST(LightTypesBadInput, SpotBeyondAHemisphereAndZeroDirectionLightWithoutAShadow) {
  init();  // before the capture: Coin's handlers are set up by the first init
  CoinMessageCapture messages;
  const std::string text = sceneWith(
      "DEF Wide SpotLight { location 0 0 1 direction 0 0 -1 cutOffAngle 2 } "
      "DEF Nowhere DirectionalLight { direction 0 0 0 }",
      "method RAYS", 0.3);
  const Image image = renderIv(text, ShadowScene::kSize);
  int wide = 0, nowhere = 0;
  for (const CoinMessageCapture::Message& m : messages.messages()) {
    wide += m.text.find("\"Wide\" lights without a shadow: cutOffAngle") != std::string::npos;
    nowhere += m.text.find("\"Nowhere\" lights without a shadow: its direction is zero") !=
               std::string::npos;
  }
  EXPECT_EQ(wide, 1);
  EXPECT_EQ(nowhere, 1);
  // Under the glass's would-be shadow (0.4, 0) the spot light (GL cuts it off at 90 degrees)
  // lights the floor unfiltered: Lambert 255 / sqrt(1 + 0.16).
  const std::uint8_t* pixel = image.pixel(160, 120);
  EXPECT_NEAR(pixel[0], 255.0 / std::sqrt(1.16), 1.5);
  EXPECT_NEAR(pixel[1], 255.0 / std::sqrt(1.16), 1.5);
}

}  // namespace
}  // namespace ivshadow::test
