// How a light's map is fitted to its casters and the view, without GL: fitMapFrame's frame
// and depth range, mapServesView's decision to keep a directional map, and fitSlices' opacity
// slices, each against values worked out by hand from the geometry (nodes/MapMethod.cpp).
#include "nodes/MapMethod.h"
#include "nodes/MapState.h"

#include <Inventor/SbBox3f.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ivshadow {
namespace {

// Single-precision arithmetic over a handful of operations (a square root, asin, cos, tan
// among them) is within a few units of the last place, about 1e-6 relative: 1e-5 is loose
// enough for that and still far below any decision these functions make.
void expectNear(double actual, double expected, const char* what) {
  EXPECT_NEAR(actual, expected, 1e-5 * (1.0 + std::abs(expected))) << what;
}

MapState pointLight(const SbVec3f& position) {
  MapState map;
  map.kind = LightKind::Point;
  map.position = position;
  return map;
}

MapState spotLight(const SbVec3f& position, const SbVec3f& axis, float cutOffAngle) {
  MapState map;
  map.kind = LightKind::Spot;
  map.position = position;
  map.axis = axis;
  map.cutOffAngle = cutOffAngle;
  return map;
}

// Light falling straight down (-z): a directional light's position is the way to the light.
MapState lightFromAbove() {
  MapState map;
  map.kind = LightKind::Directional;
  map.position = SbVec3f(0.0f, 0.0f, 1.0f);
  return map;
}

// The corners of an axis-aligned box: a view that shows [x0, x1] x [y0, y1] at every depth
// from z = -5 to 5 (only its footprint across a light from above matters).
ViewCorners viewOver(float x0, float x1, float y0, float y1) {
  ViewCorners corners;
  for (int i = 0; i < 8; ++i)
    corners[std::size_t(i)] = SbVec3f(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? 5.0f : -5.0f);
  return corners;
}

const ViewCorners kAnyView = viewOver(-1.0f, 1.0f, -1.0f, 1.0f);

// A point light outside its casters' bounding sphere sees them within asin(radius / distance)
// of the way to the sphere's centre: one face over that cone, one percent wider.
TEST(FitMapFrame, APointLightOutsideItsCastersGetsOneFaceOverTheirCone) {
  MapState map = pointLight(SbVec3f(0.0f, 0.0f, 0.0f));
  const SbBox3f casters(1.0f, 1.0f, 1.0f, 2.0f, 2.0f, 2.0f);
  fitMapFrame(map, casters, kAnyView);
  ASSERT_EQ(map.frame.projection, MapProjection::Perspective);
  EXPECT_EQ(map.frame.faceCount, 1);
  // Centre (1.5, 1.5, 1.5) at 1.5 sqrt(3), radius sqrt(3) / 2: the cone's sine is 1/3, its
  // tangent 1 / (2 sqrt(2)); the face's half-angle tangent is 1.01 times that.
  const double tanCone = 1.0 / (2.0 * std::sqrt(2.0));
  expectNear(map.frame.texelScale.x, 2.0 * 1.01 * tanCone, "the face's width at distance 1");
  const glm::vec3 axis = map.frame.faces[0].depthAxis;
  const double third = 1.0 / std::sqrt(3.0);
  expectNear(axis.x, third, "axis x");
  expectNear(axis.y, third, "axis y");
  expectNear(axis.z, third, "axis z");
  // The nearest caster point, the corner (1, 1, 1) at sqrt(3), lies at least cos(cone) =
  // sqrt(8/9) of its distance along the axis, and 1 % nearer still; the farthest corner
  // (2, 2, 2) at sqrt(12), 1 % farther.
  expectNear(map.nearRadius, 0.99 * std::sqrt(3.0) * std::sqrt(8.0 / 9.0), "near radius");
  expectNear(map.farRadius, 1.01 * std::sqrt(12.0), "far radius");
  expectNear(map.frame.farDepth, map.farRadius, "the build's far plane");
}

// Inside the casters' bounds every direction may hold one: the cube, from 1e-5 of the far
// radius (nothing is nearer than 0) to 1 % past the farthest corner.
TEST(FitMapFrame, APointLightAmongItsCastersGetsTheCube) {
  MapState map = pointLight(SbVec3f(0.0f, 0.0f, 0.0f));
  fitMapFrame(map, SbBox3f(-1.0f, -2.0f, -2.0f, 1.0f, 2.0f, 2.0f), kAnyView);
  EXPECT_EQ(map.frame.projection, MapProjection::Cube);
  EXPECT_EQ(map.frame.faceCount, 6);
  const double far = 1.01 * 3.0;  // the corner (1, 2, 2)
  expectNear(map.farRadius, far, "far radius");
  expectNear(map.nearRadius, far * 1e-5, "near radius");
}

// A spot light whose cone (0.3 rad) is narrower than its casters' (a floor wider than its
// distance, whose sphere holds the light): one face over the cone, along the spot's axis.
TEST(FitMapFrame, ANarrowSpotLightGetsOneFaceOverItsCone) {
  MapState map = spotLight(SbVec3f(0.0f, 0.0f, 2.0f), SbVec3f(0.0f, 0.0f, -1.0f), 0.3f);
  fitMapFrame(map, SbBox3f(-5.0f, -5.0f, 0.0f, 5.0f, 5.0f, 0.1f), kAnyView);
  ASSERT_EQ(map.frame.projection, MapProjection::Perspective);
  expectNear(map.frame.texelScale.x, 2.0 * 1.01 * std::tan(0.3), "the face's width");
  expectNear(map.frame.faces[0].depthAxis.z, -1.0, "along the spot's axis");
  // The floor's top is 1.9 below the light; within the cone a point lies at least cos(0.3)
  // of its distance along the axis. The farthest corner (5, 5, 0) lies sqrt(54) away.
  expectNear(map.nearRadius, 0.99 * 1.9 * std::cos(0.3), "near radius");
  expectNear(map.farRadius, 1.01 * std::sqrt(54.0), "far radius");
}

// A spot light wider than a face may be (over pi / 3) over casters that fill its view: the
// cube, whose near plane is the largest gap along one axis (1.9 down to the floor's top).
TEST(FitMapFrame, AWideSpotLightGetsTheCube) {
  MapState map = spotLight(SbVec3f(0.0f, 0.0f, 2.0f), SbVec3f(0.0f, 0.0f, -1.0f), 1.2f);
  fitMapFrame(map, SbBox3f(-5.0f, -5.0f, 0.0f, 5.0f, 5.0f, 0.1f), kAnyView);
  EXPECT_EQ(map.frame.projection, MapProjection::Cube);
  expectNear(map.nearRadius, 0.99 * 1.9, "near radius");
}

// A wide spot light over a small glass: the glass's cone (asin(0.15 / 1.95)) is the narrower,
// and the face follows it rather than the spot's cone.
TEST(FitMapFrame, ASpotLightOverSmallCastersGetsTheirNarrowerCone) {
  MapState map = spotLight(SbVec3f(0.0f, 0.0f, 2.0f), SbVec3f(0.0f, 0.0f, -1.0f), 1.0f);
  // Centre (0, 0, 0.05), 1.95 below the light; half its diagonal is sqrt(0.09) / 2 = 0.15.
  fitMapFrame(map, SbBox3f(-0.1f, -0.1f, 0.0f, 0.1f, 0.1f, 0.1f), kAnyView);
  ASSERT_EQ(map.frame.projection, MapProjection::Perspective);
  const double cone = std::asin(0.15 / 1.95);
  expectNear(map.frame.texelScale.x, 2.0 * 1.01 * std::tan(cone), "the face's width");
}

// Radii the light sets are taken as they are; a near radius past the far one is moved to
// 1e-5 of it.
TEST(FitMapFrame, RadiiTheLightSetsAreKept) {
  MapState map = pointLight(SbVec3f(0.0f, 0.0f, 0.0f));
  map.settings.nearRadius = 0.5f;
  map.settings.farRadius = 4.0f;
  const SbBox3f casters(1.0f, 1.0f, 1.0f, 2.0f, 2.0f, 2.0f);
  fitMapFrame(map, casters, kAnyView);
  EXPECT_EQ(map.nearRadius, 0.5f);
  EXPECT_EQ(map.farRadius, 4.0f);

  MapState tooShort = pointLight(SbVec3f(0.0f, 0.0f, 0.0f));
  tooShort.settings.farRadius = 0.1f;  // nearer than any caster: the fitted near radius is past it
  fitMapFrame(tooShort, casters, kAnyView);
  EXPECT_EQ(tooShort.farRadius, 0.1f);
  expectNear(tooShort.nearRadius, 0.1 * 1e-5, "near radius");
}

// A directional light's map covers what the view shows of the casters, a quarter wider on
// each side, across the light; along it, the casters' whole depth and 1 % more either side.
TEST(FitMapFrame, ADirectionalMapCoversTheVisibleCastersWithAMargin) {
  MapState map = lightFromAbove();
  const SbBox3f casters(-1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 0.5f);
  fitMapFrame(map, casters, viewOver(-0.4f, 0.4f, -0.4f, 0.4f));
  ASSERT_EQ(map.frame.projection, MapProjection::Orthographic);
  // The view's 0.8 wide square, 0.2 more on every side: 1.2 wide, centred on the light's axis.
  for (int i = 0; i < 2; ++i) {
    expectNear(map.coveredLow[i], -0.6, "covered from");
    expectNear(map.coveredHigh[i], 0.6, "covered to");
  }
  // The casters lie 0.5 deep along the light; 1 % of that and 1e-4 of a unit either side.
  const double pad = 0.01 * 0.5 + 1e-4;
  EXPECT_EQ(map.nearRadius, 0.0f);
  expectNear(map.farRadius, 0.5 + 2.0 * pad, "far radius");

  // Seen whole, the casters bound the margin: the view's 1.8 plus 0.45 a side stops at 2.
  MapState wide = lightFromAbove();
  fitMapFrame(wide, casters, viewOver(-0.9f, 0.9f, -0.9f, 0.9f));
  for (int i = 0; i < 2; ++i) expectNear(wide.coveredHigh[i] - wide.coveredLow[i], 2.0, "width");
}

// A view that shows none of what the casters shadow gets a map of no extent across the light.
TEST(FitMapFrame, ADirectionalMapOfAViewBesideTheCastersCoversNothing) {
  MapState map = lightFromAbove();
  fitMapFrame(map, SbBox3f(-1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 0.5f), viewOver(5.0f, 6.0f, 5.0f, 6.0f));
  EXPECT_EQ(map.coveredLow.x, map.coveredHigh.x);
  EXPECT_EQ(map.coveredLow.y, map.coveredHigh.y);
}

// The map fitted to a view 0.8 wide covers 1.2: it serves views that stay inside it and need
// at least a third of its width.
class MapServesView : public ::testing::Test {
 protected:
  void SetUp() override { fitMapFrame(map_, kCasters, viewOver(-0.4f, 0.4f, -0.4f, 0.4f)); }
  bool serves(const ViewCorners& view) const { return mapServesView(map_, kCasters, view); }

  const SbBox3f kCasters{-1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 0.5f};
  MapState map_ = lightFromAbove();
};

TEST_F(MapServesView, TheViewItWasFittedTo) {
  EXPECT_TRUE(serves(viewOver(-0.4f, 0.4f, -0.4f, 0.4f)));
}

TEST_F(MapServesView, AViewMovedWithinTheMargin) {
  // [-0.25, 0.55] stays inside [-0.6, 0.6].
  EXPECT_TRUE(serves(viewOver(-0.25f, 0.55f, -0.4f, 0.4f)));
}

TEST_F(MapServesView, NotAViewMovedPastTheMargin) {
  // [-0.1, 0.7] leaves the map at 0.6.
  EXPECT_FALSE(serves(viewOver(-0.1f, 0.7f, -0.4f, 0.4f)));
}

TEST_F(MapServesView, NotAViewOverThreeTimesNarrowerThanTheMap) {
  // 0.5 wide: three times that (1.5) still covers the map's 1.2; 0.3 wide (0.9) does not, and
  // most of the map's texels would be spent outside the view.
  EXPECT_TRUE(serves(viewOver(-0.25f, 0.25f, -0.25f, 0.25f)));
  EXPECT_FALSE(serves(viewOver(-0.15f, 0.15f, -0.15f, 0.15f)));
}

TEST_F(MapServesView, AViewThatShowsNothingShadowed) {
  EXPECT_TRUE(serves(viewOver(5.0f, 6.0f, 5.0f, 6.0f)));
}

// Only a directional map depends on the view.
TEST(MapServesViewOfOtherLights, APointOrSpotLightsMapServesEveryView) {
  const SbBox3f casters(-1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 0.5f);
  MapState point = pointLight(SbVec3f(0.0f, 0.0f, 3.0f));
  fitMapFrame(point, casters, viewOver(-0.4f, 0.4f, -0.4f, 0.4f));
  EXPECT_TRUE(mapServesView(point, casters, viewOver(3.0f, 3.1f, 3.0f, 3.1f)));
  MapState spot = spotLight(SbVec3f(0.0f, 0.0f, 3.0f), SbVec3f(0.0f, 0.0f, -1.0f), 0.5f);
  fitMapFrame(spot, casters, viewOver(-0.4f, 0.4f, -0.4f, 0.4f));
  EXPECT_TRUE(mapServesView(spot, casters, viewOver(3.0f, 3.1f, 3.0f, 3.1f)));
}

// A map whose depth range runs from `near` to `far` around a light at the origin.
MapState mapWithRange(float near, float far) {
  MapState map = pointLight(SbVec3f(0.0f, 0.0f, 0.0f));
  map.nearRadius = near;
  map.farRadius = far;
  return map;
}

// A cube face stores a point's largest coordinate from the light: over the glass
// [1, 2] x [-0.5, 0.5]^2 that runs from 1 (its near side) to 2 (its far side); the slices
// reach 1 % of that, and 1e-4 of (1 + 2) units, past either end.
TEST(FitSlices, ACubeMapsSlicesSpanTheGlassesAxialDistances) {
  MapState map = mapWithRange(0.01f, 10.0f);
  ASSERT_EQ(map.frame.projection, MapProjection::Cube);
  fitSlices(map, SbBox3f(1.0f, -0.5f, -0.5f, 2.0f, 0.5f, 0.5f));
  const double pad = 0.01 * 1.0 + 1e-4 * 3.0;
  expectNear(map.sliceNear, 1.0 - pad, "first slice");
  expectNear(map.sliceFar, 2.0 + pad, "last slice");
}

// One face stores the distance along its axis from its origin: 3 - z for a face at z = 3
// looking down, 2 to 2.5 over a glass from z = 0.5 to 1.
MapState faceLookingDown(float near, float far) {
  MapState map = mapWithRange(near, far);
  map.frame.projection = MapProjection::Orthographic;
  map.frame.faceCount = 1;
  map.frame.faces[0].depthOrigin = glm::vec3(0.0f, 0.0f, 3.0f);
  map.frame.faces[0].depthAxis = glm::vec3(0.0f, 0.0f, -1.0f);
  return map;
}
const SbBox3f kGlass(-1.0f, -1.0f, 0.5f, 1.0f, 1.0f, 1.0f);

TEST(FitSlices, AOneFaceMapsSlicesSpanTheGlassesDepthAlongTheFace) {
  MapState map = faceLookingDown(0.01f, 10.0f);
  fitSlices(map, kGlass);
  const double pad = 0.01 * 0.5 + 1e-4 * 3.5;
  expectNear(map.sliceNear, 2.0 - pad, "first slice");
  expectNear(map.sliceFar, 2.5 + pad, "last slice");
}

TEST(FitSlices, TheSlicesStayWithinTheMapsRange) {
  MapState map = faceLookingDown(2.2f, 2.3f);
  fitSlices(map, kGlass);
  EXPECT_EQ(map.sliceNear, 2.2f);
  EXPECT_EQ(map.sliceFar, 2.3f);
}

// A glass wholly outside the range would leave no slice: the slices take the whole range.
TEST(FitSlices, AGlassOutsideTheRangeSlicesTheWholeRange) {
  MapState map = faceLookingDown(0.01f, 0.5f);
  fitSlices(map, kGlass);
  EXPECT_EQ(map.sliceNear, 0.01f);
  EXPECT_EQ(map.sliceFar, 0.5f);
}

TEST(FitSlices, RadiiTheLightSetsAreTheSlicesToo) {
  MapState map = faceLookingDown(0.01f, 10.0f);
  map.settings.farRadius = 10.0f;
  fitSlices(map, kGlass);
  EXPECT_EQ(map.sliceNear, 0.01f);
  EXPECT_EQ(map.sliceFar, 10.0f);
}

// Without transparent casters the slices hold nothing: they keep the map's range.
TEST(FitSlices, NoGlassSlicesTheWholeRange) {
  MapState map = faceLookingDown(0.01f, 10.0f);
  fitSlices(map, SbBox3f());
  EXPECT_EQ(map.sliceNear, 0.01f);
  EXPECT_EQ(map.sliceFar, 10.0f);
}

}  // namespace
}  // namespace ivshadow
