// Cameras at the edge (issue 36). What a camera shows does not depend on its near and far
// planes while the scene lies between them; the tracer inverted the projection in floats and
// lost its rays for a near plane at 1e-11 or a far one at 1e12 (Coin's float projection then
// puts the far plane at infinity), giving a black picture where GL draws the scene. A
// perspective camera with a negative nearDistance shows nothing in GL, and so in plain Coin;
// the tracer and the reference drew the scene.
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/ShadowScene.h"

#include <gtest/gtest.h>

#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kSize = 64;

std::string scene(const std::string& planes, const std::string& group,
                  const char* camera = "PerspectiveCamera") {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << camera << " { position 0 0 5 " << planes << " }\n"
     << (group.empty() ? std::string("Separator {") : "TransparentShadowGroup { " + group) << "\n"
     << "PointLight { location 0 0 3 }\n"
     << "Coordinate3 { point [ -1 1 0, 1 1 0, -1 -1 0, 1 -1 0 ] }\n"
     << "QuadMesh { verticesPerRow 2 verticesPerColumn 2 }\n"
     << "Material { diffuseColor 1 0 0 transparency 0.5 }\n"
     << "Coordinate3 { point [ -0.3 -0.3 0.5, 0.3 -0.3 0.5, 0.3 0.3 0.5, -0.3 0.3 0.5 ] }\n"
     << "FaceSet { numVertices 4 }\n}\n}\n";
  return iv.str();
}

Image traced(const std::string& planes, bool reference, const char* camera = "PerspectiveCamera") {
  const std::string text = scene(planes, "renderer TRACER", camera);
  return reference ? referenceIv(text, kSize) : renderIv(text, kSize);
}

int largestDifference(const Image& a, const Image& b) {
  int largest = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
  return largest;
}

class CameraEdge : public ::testing::TestWithParam<bool> {};

TEST_P(CameraEdge, ExtremeNearAndFarPlanesShowWhatOrdinaryOnesShow) {
  const bool reference = GetParam();
  const Image ordinary = traced("nearDistance 1 farDistance 10", reference);
  // The ordinary picture is not empty: the comparisons below can tell a black picture.
  EXPECT_GT(ordinary.pixel(kSize / 2, kSize / 2)[0], 100);
  for (const char* planes : {"nearDistance 1e-11 farDistance 10", "nearDistance 1 farDistance 1e12",
                             "nearDistance 1e-6 farDistance 1e6"}) {
    SCOPED_TRACE(planes);
    // One 8-bit step: the rays start at another point of the same line.
    EXPECT_LE(largestDifference(traced(planes, reference), ordinary), 1);
  }
}

TEST_P(CameraEdge, ANegativeNearDistanceShowsWhatPlainCoinShows) {
  const std::string planes = "nearDistance -1 farDistance 10";
  const Image coin = renderIv(scene(planes, ""), kSize);
  // Plain Coin draws nothing: GL clips every point in front of such a camera.
  const Image empty = renderIv(scene(planes, "renderer RASTER"), kSize);
  EXPECT_EQ(largestDifference(coin, empty), 0);
  EXPECT_EQ(coin.pixel(kSize / 2, kSize / 2)[0], 0);
  EXPECT_EQ(largestDifference(traced(planes, GetParam()), coin), 0);
}

// An orthographic camera may look from behind its position (GL draws what lies between the
// planes either way): its rays start 100 units behind the eye and must still reach the scene
// (found in review: they ended a scene's distance from the eye, short of it).
TEST_P(CameraEdge, AnOrthographicCameraWithANegativeNearDistanceShowsTheScene) {
  const bool reference = GetParam();
  const Image ordinary =
      traced("nearDistance 1 farDistance 10 height 2.4", reference, "OrthographicCamera");
  EXPECT_GT(ordinary.pixel(kSize / 2, kSize / 2)[0], 100);
  const Image behind =
      traced("nearDistance -100 farDistance 100 height 2.4", reference, "OrthographicCamera");
  // One 8-bit step: the rays start at another point of the same line.
  EXPECT_LE(largestDifference(behind, ordinary), 1);
}

INSTANTIATE_TEST_SUITE_P(Paths, CameraEdge, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return std::string(info.param ? "Reference" : "Tracer");
                         });

}  // namespace
}  // namespace ivshadow::test
