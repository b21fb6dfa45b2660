#include "ivshadow/DeepShadowStatistics.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoNode.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ivshadow::test {
namespace {

// Every checked pixel is the floor's Lambert value times the filters' transmittance. The
// group shades per pixel in single precision: the only error is rounding to 8 bits (half a
// step) plus float error far below a step, and the cube map is sampled well inside each
// shadow (edges are excluded by ShadowPicture's 2-pixel margin, the bound on where
// the footprint edges may fall). One 8-bit step bounds it.
constexpr double kTolerance = 1.0;

void expectPicture(const ShadowScene& scene, const ShadowPicture& picture,
                   SoNode** root = nullptr) {
  const Image image = renderIv(scene.text(), ShadowScene::kSize, root);
  const std::string failure = compareWithExpectation(image, picture, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The map of each analytic case (ShadowScene.h) gives its picture within one step.
class DeepShadowAnalytic : public ::testing::TestWithParam<AnalyticCase> {};

TEST_P(DeepShadowAnalytic, MatchesThePicture) {
  expectPicture(GetParam().scene, GetParam().picture());
}

INSTANTIATE_TEST_SUITE_P(Cases, DeepShadowAnalytic, ::testing::ValuesIn(analyticCases()),
                         analyticCaseName);

TEST(DeepShadow, HalfPrecisionAndPcfKeepTheInterior) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene.lightFields = "precision HALF filter PCF filterSize 3";
  // Half floats hold 0.25 to 1e-4: far below an 8-bit step. PCF's 3 x 3 kernel reaches one
  // texel (0.4 pixel here) beyond the edge, inside the 2-pixel margin.
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate});
}

TEST(DeepShadow, MaxLayersTruncatedKeepsOnlyTheNearestSurfaces) {
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightFields = "maxLayers 1 layerOverflow TRUNCATE";
  ShadowPicture picture{&scene, ColourModel::Saturate};
  picture.maxLayers = 1;  // documented: surfaces beyond the first maxLayers are ignored
  expectPicture(scene, picture);
}

// The default, layerOverflow MERGE: where the two filters overlap, their two surfaces share
// the one layer, stored at the nearer one's distance with the light left after both. The
// floor behind them gets every surface's transmittance, as with layers enough (the picture
// counts all of them); only a point between the two (the lower filter itself, which the
// picture does not check) gets the merge's error, which the statistics report.
TEST(DeepShadow, SurfacesPastMaxLayersAreMergedSoTheFloorBehindThemIsExact) {
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.lightFields = "maxLayers 1";
  SoNode* root = nullptr;
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate}, &root);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  root->unref();
  ASSERT_EQ(stats.lights.size(), 1u);
  EXPECT_EQ(stats.lights[0].mapBuild, "FRAGMENT_LISTS");
  EXPECT_GT(stats.lights[0].mergedTexels, 0u);
  // The light the lower filter's surface gets wrong: the upper one's transmittance less
  // both's, at most 1.
  EXPECT_GT(stats.lights[0].mergeError, 0.0f);
  EXPECT_LE(stats.lights[0].mergeError, 1.0f);
}

// More transparent surfaces along the light's rays than the map keeps layers (five glasses,
// maxLayers 4), then an opaque square (half size 0.3 at height 0.2, shadow out to 0.375):
// light must not pass the opaque body. The floor in its shadow, where it is not hidden from
// the camera by the square itself (0.3 < max(|x|, |y|) < 0.375, 2-pixel margins), is black;
// beyond every shadow (max(|x|, |y|) > 0.67) it is Lambert's 255 / sqrt(1 + r^2).
TEST(DeepShadow, LayersRunningOutNeverLetLightThroughAnOpaqueBody) {
  ShadowScene scene;
  scene.lightFields = "maxLayers 4";
  for (double height : {0.7, 0.6, 0.55, 0.5}) scene.filters.push_back(Filter{0.2, height});
  scene.filters.push_back(Filter{0.25, 0.45});
  Filter opaque{0.3, 0.2};
  opaque.transparency = 0.0;
  scene.filters.push_back(opaque);
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
  int shadowed = 0, lit = 0;
  for (int py = 0; py < ShadowScene::kSize; ++py)
    for (int px = 0; px < ShadowScene::kSize; ++px) {
      const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
      const double extent = std::max(std::abs(x), std::abs(y));
      const std::uint8_t* p = image.pixel(px, py);
      if (extent > 0.32 && extent < 0.355) {
        ++shadowed;
        EXPECT_LE(std::max({p[0], p[1], p[2]}), 1)
            << "light through the opaque body at " << px << "," << py;
      } else if (extent > 0.69 && extent < 0.98) {
        ++lit;
        EXPECT_NEAR(p[0], 255.0 / std::sqrt(1.0 + x * x + y * y), kTolerance) << px << "," << py;
      }
    }
  EXPECT_EQ(shadowed, 70 * 70 - 64 * 64);  // the pixel centres of the band
  EXPECT_GT(lit, 10000);
}

TEST(DeepShadow, FragmentListsDrawEachFaceOnceAndKeepOnlyTheLayersUsed) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  SoNode* root = nullptr;
  renderIv(scene.text(), ShadowScene::kSize, &root);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  root->unref();
  ASSERT_EQ(stats.lights.size(), 1u);
  const auto& light = stats.lights[0];
  // Face 5 (-z) sees the glass then the opaque floor: two layers, the floor's the last one the
  // peel would keep. The other faces see nothing. The fragment lists draw every face once
  // (the first build's storage holds one surface for every two texels of the cube: enough).
  EXPECT_EQ(light.layersUsed, (std::array<int, 6>{0, 0, 0, 0, 0, 2}));
  EXPECT_EQ(light.passes, (std::array<int, 6>{1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(light.mapBuild, "FRAGMENT_LISTS");
  EXPECT_TRUE(light.coloured);
  EXPECT_EQ(stats.rebuilds, 1);
  // Only the two used layers are kept: 512^2 texels x (32-bit depth + RGBA32F visibility).
  EXPECT_EQ(light.bytes, 512ull * 512ull * 2ull * (4ull + 16ull));
}

TEST(DeepShadow, GreyCastersGetAMonochromeMapInAutoMode) {
  ShadowScene scene;
  Filter grey = kRedGlass;
  grey.diffuse = {0.5, 0.5, 0.5};
  scene.filters = {grey};
  SoNode* root = nullptr;
  const Image image = renderIv(scene.text(), ShadowScene::kSize, &root);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  root->unref();
  ASSERT_EQ(stats.lights.size(), 1u);
  EXPECT_FALSE(stats.lights[0].coloured);
  const std::string failure =
      compareWithExpectation(image, ShadowPicture{&scene, ColourModel::Monochrome}, kTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The same picture seen through each cube face in turn, and across seams: the group's
// content is rotated inside the group and back outside it.
struct FaceCase {
  const char* name;
  std::array<double, 3> axis;
  double angle;
  int face;  // the face the floor's centre falls on, -1 for a seam or corner
};

class DeepShadowFaces : public ::testing::TestWithParam<FaceCase> {};

TEST_P(DeepShadowFaces, EveryDirectionGivesTheSamePicture) {
  const FaceCase& c = GetParam();
  ShadowScene scene;
  scene.filters = {kRedGlass, kGreenGlass};
  scene.rotationAxis = c.axis;
  scene.rotationAngle = c.angle;
  SoNode* root = nullptr;
  expectPicture(scene, ShadowPicture{&scene, ColourModel::Saturate}, &root);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  root->unref();
  ASSERT_EQ(stats.lights.size(), 1u);
  if (c.face >= 0) EXPECT_GE(stats.lights[0].layersUsed[std::size_t(c.face)], 3);
}

const double kHalfPi = std::acos(0.0);
INSTANTIATE_TEST_SUITE_P(
    AllFacesAndSeams, DeepShadowFaces,
    ::testing::Values(
        FaceCase{"minusZ", {0, 0, 1}, 0.0, 5}, FaceCase{"plusZ", {1, 0, 0}, 2 * kHalfPi, 4},
        FaceCase{"minusX", {0, 1, 0}, kHalfPi, 1}, FaceCase{"plusX", {0, 1, 0}, -kHalfPi, 0},
        FaceCase{"plusY", {1, 0, 0}, kHalfPi, 2}, FaceCase{"minusY", {1, 0, 0}, -kHalfPi, 3},
        // The floor's centre on the seam of two faces, and on a cube corner.
        FaceCase{"seam", {0, 1, 0}, -kHalfPi / 2, -1},
        FaceCase{"corner", {1, -1, 0}, std::acos(1.0 / std::sqrt(3.0)), -1}),
    [](const ::testing::TestParamInfo<FaceCase>& info) { return std::string(info.param.name); });

TEST(DeepShadow, AlphaTexturedCheckerboardCastsACheckerboard) {
  ShadowScene scene;
  const Filter checker = checkerboardFilter();
  scene.filters = {checker};
  SoNode* root = nullptr;
  const Image image = renderIv(scene.text(), ShadowScene::kSize, &root);
  root->unref();
  // Floor points in the ring around the seen glass whose light passes each quadrant:
  // (x, y) on the floor maps to (x, y) / 2 on the glass.
  expectCheckerboardShadow(image, kTolerance);
}

}  // namespace
}  // namespace ivshadow::test
