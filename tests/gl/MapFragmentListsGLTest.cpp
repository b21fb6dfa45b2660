// Deep shadow maps built from fragment lists (gl/MapFragmentLists) on their own, through
// DeepShadowPass: a stack of squares across one orthographic face against the layers computed
// here from their heights and colours (seeds/000 eq. 5.3), and random scenes against the map
// the peel passes build from the same casters, texel for texel.
#include "gl/DeepShadowMapReadback.h"
#include "gl/DeepShadowPass.h"
#include "gl/MapFrame.h"
#include "scene/SceneTriangles.h"
#include "tests/gl/GlContextTest.h"
#include "tests/gl/MapSquares.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

class MapFragmentListsGLTest : public GlContextTest {
 protected:
  std::unique_ptr<DeepShadowPass> makePass() { return makeMapPass(); }
};

TEST_F(MapFragmentListsGLTest, AStackOfSquaresGivesItsLayersInOneDraw) {
  auto pass = makePass();
  ASSERT_TRUE(pass);
  // Drawn far to near, so that the lists' order (latest first) is not the answer: an opaque
  // floor at 0.5, green glass (opacity 0.25) at 2, red glass (opacity 0.5) at 3, all across
  // the face; and a small blue pane at 3.5 over the corner x, y > 0.5 only.
  const std::vector<Square> squares = {{0, 0, 2, 0.5f, {0.5f, 0.5f, 0.5f, 1.0f}},
                                       {0, 0, 2, 2.0f, {0.1f, 0.9f, 0.1f, 0.25f}},
                                       {0, 0, 2, 3.0f, {0.9f, 0.1f, 0.1f, 0.5f}},
                                       {0.75f, 0.75f, 0.25f, 3.5f, {0.1f, 0.1f, 0.9f, 0.5f}}};
  pass->uploadCasters(trianglesOf(squares));
  const MapRequest request = downwards(64, 4, true);
  // The first build grows the lists to what the map needs (three surfaces a texel, six times
  // the first storage); the next draws once.
  EXPECT_EQ(pass->build(0, request).passes[0], 2);
  const MapBuildResult built = pass->build(0, request);
  ASSERT_TRUE(built.failure.empty()) << built.failure;
  EXPECT_TRUE(built.fragmentLists) << built.listFailure;
  EXPECT_EQ(built.passes[0], 1);
  // The corner's texels hold four surfaces, the rest three; the floor stops the peel.
  EXPECT_EQ(built.layersUsed[0], 4);
  // 64 x 64 texels: 3 surfaces each, and the blue pane's 16 x 16.
  EXPECT_EQ(built.listFragments, 64u * 64u * 3u + 16u * 16u);

  std::vector<MapLayerReadback> layers(4);
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(pass->readMapLayer(0, k, layers[std::size_t(k)]));
  const auto expectTexel = [&](int x, int y, const std::vector<const Square*>& crossed) {
    SCOPED_TRACE("texel " + std::to_string(x) + "," + std::to_string(y));
    const std::size_t texel = std::size_t(y) * 64 + std::size_t(x);
    float visibility[3] = {1.0f, 1.0f, 1.0f};
    for (std::size_t k = 0; k < 4; ++k) {
      const MapLayerReadback& layer = layers[k];
      if (k >= crossed.size()) {
        // Empty layers hold the largest float, which stops a lookup.
        EXPECT_EQ(layer.depth[texel], 3.40282347e+38f);
        continue;
      }
      const Square& s = *crossed[k];
      // Distances are differences of exactly representable heights: exact. The products are
      // the same float multiplications in the same order as here: within one rounding each.
      EXPECT_EQ(layer.depth[texel], 4.0f - s.z);
      for (int c = 0; c < 3; ++c) {
        visibility[c] *= saturate(s.colour[c], s.colour[3]);
        EXPECT_NEAR(layer.visibility[texel * 3 + std::size_t(c)], visibility[c], 1e-6f);
      }
    }
  };
  // Where each texel's centre lies: the face's lookup (x w, y w, depth, w) inverted.
  const glm::mat4 toFace = glm::inverse(request.frame.lookup);
  int inCorner = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::vec4 p =
          toFace * glm::vec4((x + 0.5f) / 32.0f - 1.0f, (y + 0.5f) / 32.0f - 1.0f, 0.5f, 1.0f);
      const bool corner = p.x / p.w > 0.5f && p.y / p.w > 0.5f;
      inCorner += corner ? 1 : 0;
      if (corner)
        expectTexel(x, y, {&squares[3], &squares[2], &squares[1], &squares[0]});
      else
        expectTexel(x, y, {&squares[2], &squares[1], &squares[0]});
    }
  EXPECT_EQ(inCorner, 16 * 16);
}

// Squares of random place, size, height, colour and opacity (a third opaque, some exactly
// on one another's height, so that ties are ordered by triangle number) under a point light
// at the centre of a cube map, some beside and above it.
SceneTriangles randomScene(unsigned seed, int count) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Square> squares;
  for (int i = 0; i < count; ++i) {
    Square s{};
    s.x = 4.0f * unit(random) - 2.0f;
    s.y = 4.0f * unit(random) - 2.0f;
    s.half = 0.2f + unit(random);
    // Heights on a grid of eighths: several squares share one.
    s.z = std::round(8.0f * (4.0f * unit(random) - 3.0f)) / 8.0f;
    for (int c = 0; c < 3; ++c) s.colour[c] = unit(random);
    s.colour[3] = unit(random) < 0.33f ? 1.0f : 0.1f + 0.8f * unit(random);
    squares.push_back(s);
  }
  return trianglesOf(squares);
}

void expectSameMaps(DeepShadowPass& lists, DeepShadowPass& peeled, const MapBuildResult& a,
                    const MapBuildResult& b, int faceCount) {
  ASSERT_TRUE(a.fragmentLists) << a.listFailure;
  ASSERT_FALSE(b.fragmentLists);
  EXPECT_EQ(a.layersUsed, b.layersUsed);
  EXPECT_EQ(a.firstLayer, b.firstLayer);
  int total = 0;
  for (int face = 0; face < faceCount; ++face) total += b.layersUsed[std::size_t(face)];
  ASSERT_GT(total, 0);
  for (int layer = 0; layer < total; ++layer) {
    MapLayerReadback x, y;
    ASSERT_TRUE(lists.readMapLayer(0, layer, x));
    ASSERT_TRUE(peeled.readMapLayer(0, layer, y));
    // The same surfaces in the same order and the same float products: bit for bit.
    EXPECT_EQ(x.depth, y.depth) << "layer " << layer;
    EXPECT_EQ(x.visibility, y.visibility) << "layer " << layer;
  }
}

struct Variant {
  int layers;
  bool coloured;
  bool half;
};

class MapFragmentListsAgainstPeeling : public MapFragmentListsGLTest,
                                       public ::testing::WithParamInterface<Variant> {};

TEST_P(MapFragmentListsAgainstPeeling, StoreTheMapThePeelStores) {
  const Variant variant = GetParam();
  auto lists = makePass(), peeled = makePass();
  ASSERT_TRUE(lists && peeled);
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const SceneTriangles scene = randomScene(seed, 40);
    lists->uploadCasters(scene);
    peeled->uploadCasters(scene);
    MapRequest request;
    request.frame = cubeFrame({0.0f, 0.0f, 1.5f}, 0.05f, 8.0f);
    request.resolution = 96;
    request.layers = variant.layers;
    request.coloured = variant.coloured;
    request.halfPrecision = variant.half;
    request.colourModel =
        variant.coloured ? ShadowColourModel::Saturate : ShadowColourModel::Monochrome;
    const MapBuildResult a = lists->build(0, request);
    request.fragmentLists = false;
    const MapBuildResult b = peeled->build(0, request);
    expectSameMaps(*lists, *peeled, a, b, 6);
    // With few layers kept, some face's layers run out over glass: the closing layer.
    if (variant.layers == 1)
      EXPECT_TRUE(std::any_of(b.layersUsed.begin(), b.layersUsed.end(),
                              [&](int used) { return used == variant.layers + 1; }));
    // A directional light's face, whose near plane lies on the highest squares (height 1):
    // their distance is 0, where a depth below it would be clamped.
    request.frame =
        orthographicFrame({0.0f, 0.0f, -1.0f}, {-3.0f, -3.0f, -1.0f}, {3.0f, 3.0f, 3.0f});
    request.fragmentLists = true;
    const MapBuildResult c = lists->build(0, request);
    request.fragmentLists = false;
    const MapBuildResult d = peeled->build(0, request);
    expectSameMaps(*lists, *peeled, c, d, 1);
  }
}

INSTANTIATE_TEST_SUITE_P(Layers, MapFragmentListsAgainstPeeling,
                         ::testing::Values(Variant{1, true, false}, Variant{2, true, false},
                                           Variant{4, true, false}, Variant{8, false, false},
                                           Variant{4, true, true}, Variant{3, false, true}),
                         [](const ::testing::TestParamInfo<Variant>& info) {
                           return "layers" + std::to_string(info.param.layers) +
                                  (info.param.coloured ? "Coloured" : "Grey") +
                                  (info.param.half ? "Half" : "Float");
                         });

// The peel goes on past a layer while any surface behind it lets light through, whatever its
// rank, not only while that layer's does: an opaque square in front of glass keeps the glass's
// layer (visibility 0) and, with two layers, the closing one of the opaque floor behind. The
// lists must count the same layers.
TEST_F(MapFragmentListsGLTest, GlassBehindAnOpaqueLayerKeepsThePeelsLayers) {
  const Square nearOpaque{0, 0, 2, 3.0f, {0.5f, 0.5f, 0.5f, 1.0f}};
  const Square glass{0, 0, 2, 2.0f, {0.2f, 0.8f, 0.3f, 0.5f}};
  const Square floor{0, 0, 2, 1.0f, {0.5f, 0.5f, 0.5f, 1.0f}};
  struct Case {
    int layers;
    std::vector<Square> squares;
    int kept;  // as the peel counts them: 2 passes that stored, or 2 and the closing layer
  };
  for (const Case& c : {Case{4, {glass, nearOpaque}, 2}, Case{2, {floor, glass, nearOpaque}, 3}}) {
    SCOPED_TRACE("maxLayers " + std::to_string(c.layers));
    auto lists = makePass(), peeled = makePass();
    ASSERT_TRUE(lists && peeled);
    lists->uploadCasters(trianglesOf(c.squares));
    peeled->uploadCasters(trianglesOf(c.squares));
    const MapBuildResult a = lists->build(0, downwards(32, c.layers, true));
    const MapBuildResult b = peeled->build(0, downwards(32, c.layers, false));
    EXPECT_EQ(b.layersUsed[0], c.kept);
    expectSameMaps(*lists, *peeled, a, b, 1);
  }
}

// A map built again stores its layers in the last build's layout with the same sort that
// counts them, and sorts a second time only where the layers changed: a pane moved across
// the face keeps the layout (one sort), a pane added changes it (two). Each map is the peel's.
TEST_F(MapFragmentListsGLTest, AMapBuiltAgainSortsOnceWhileItsLayoutHolds) {
  std::vector<Square> squares = {{0, 0, 2, 0.5f, {0.5f, 0.5f, 0.5f, 1.0f}},
                                 {0, 0, 2, 2.0f, {0.1f, 0.9f, 0.1f, 0.25f}},
                                 {-0.5f, -0.5f, 0.25f, 3.0f, {0.9f, 0.1f, 0.1f, 0.5f}}};
  auto lists = makePass(), peeled = makePass();
  ASSERT_TRUE(lists && peeled);
  const auto buildBoth = [&](int sorts) {
    lists->uploadCasters(trianglesOf(squares));
    peeled->uploadCasters(trianglesOf(squares));
    const MapBuildResult a = lists->build(0, downwards(64, 4, true));
    const MapBuildResult b = peeled->build(0, downwards(64, 4, false));
    EXPECT_EQ(a.listSorts, sorts);
    expectSameMaps(*lists, *peeled, a, b, 1);
  };
  {
    SCOPED_TRACE("first build");
    buildBoth(2);
  }
  {
    SCOPED_TRACE("the same again");
    buildBoth(1);
  }
  squares[2].x = 0.5f;
  {
    SCOPED_TRACE("the pane moved");
    buildBoth(1);
  }
  squares.push_back({0, 0, 2, 3.5f, {0.2f, 0.2f, 0.9f, 0.5f}});
  {
    SCOPED_TRACE("a pane added");
    buildBoth(2);
  }
}

TEST_F(MapFragmentListsGLTest, AMapTheStorageDoesNotHoldIsDrawnAgainLargerOnce) {
  // Ten squares across the face: ten surfaces a texel, twenty times the first storage (one
  // surface for every two texels). The first build draws again with a larger buffer; the
  // second, which keeps it, draws once.
  std::vector<Square> squares;
  for (int i = 0; i < 10; ++i)
    squares.push_back({0, 0, 2, 0.25f + 0.25f * float(i), {0.8f, 0.4f, 0.2f, 0.3f}});
  const SceneTriangles scene = trianglesOf(squares);
  auto lists = makePass(), peeled = makePass();
  ASSERT_TRUE(lists && peeled);
  lists->uploadCasters(scene);
  peeled->uploadCasters(scene);
  const MapBuildResult first = lists->build(0, downwards(64, 8, true));
  EXPECT_EQ(first.passes[0], 2);
  EXPECT_EQ(first.listFragments, 64u * 64u * 10u);
  const MapBuildResult second = lists->build(0, downwards(64, 8, true));
  EXPECT_EQ(second.passes[0], 1);
  const MapBuildResult reference = peeled->build(0, downwards(64, 8, false));
  // Eight layers of glass and the closing layer: no opaque surface behind them, none stored.
  EXPECT_EQ(reference.layersUsed[0], 8);
  expectSameMaps(*lists, *peeled, second, reference, 1);
}

TEST_F(MapFragmentListsGLTest, ListsBeyondTheirByteLimitArePeeledAndSaySo) {
  std::vector<Square> squares;
  for (int i = 0; i < 6; ++i)
    squares.push_back({0, 0, 2, 0.5f + 0.5f * float(i), {0.2f, 0.4f, 0.8f, 0.4f}});
  auto pass = makePass(), peeled = makePass();
  ASSERT_TRUE(pass && peeled);
  pass->uploadCasters(trianglesOf(squares));
  peeled->uploadCasters(trianglesOf(squares));
  // 128 x 128 texels of 6 surfaces need 3 MiB of 32-byte fragments; allowed 1 MiB.
  MapRequest request = downwards(128, 4, true);
  request.listByteLimit = 1u << 20;
  const MapBuildResult built = pass->build(0, request);
  EXPECT_FALSE(built.fragmentLists);
  EXPECT_NE(built.listFailure.find("more than the 1 MiB the memory budget leaves"),
            std::string::npos)
      << built.listFailure;
  request.fragmentLists = false;
  request.listByteLimit = 0;
  const MapBuildResult reference = peeled->build(0, request);
  EXPECT_EQ(built.layersUsed, reference.layersUsed);
  EXPECT_EQ(built.passes, reference.passes);
  MapLayerReadback a, b;
  ASSERT_TRUE(pass->readMapLayer(0, 3, a));
  ASSERT_TRUE(peeled->readMapLayer(0, 3, b));
  EXPECT_EQ(a.visibility, b.visibility);
}

}  // namespace
}  // namespace ivshadow::test
