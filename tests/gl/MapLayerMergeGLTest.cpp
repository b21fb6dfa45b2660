// Deep shadow maps whose texels hold more surfaces that let light through than maxLayers,
// built from fragment lists with MapRequest::mergeOverflow (SoDeepShadowLight::layerOverflow
// MERGE): random stacks of glass across one orthographic face, drawn in random order, against
// the visibility computed here from their heights and colours (seeds/000 eq. 5.3), and random
// scenes against the same lists without merging, which store the peel's map.
#include "gl/DeepShadowMapReadback.h"
#include "gl/DeepShadowPass.h"
#include "gl/MapFrame.h"
#include "tests/gl/GlContextTest.h"
#include "tests/gl/MapSquares.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

class MapLayerMergeGLTest : public GlContextTest {};

// A stack of `glass` panes across the face (so that every texel holds all of them) on a grid
// of eighths between 0.5 and 3.5, some pairs at one height (a pane and its twin: no point
// lies between them), with an opaque floor at 0.25 and, below the floor, panes no light
// reaches. The map keeps colours in FLOAT, or one channel in HALF.
struct Stack {
  std::vector<Square> glass;  // in the order they are drawn
  bool floor = false;
  std::vector<Square> belowFloor;
  int layers = 1;
  bool coloured = true;
};

Stack randomStack(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Stack stack;
  stack.layers = std::array<int, 5>{1, 2, 3, 4, 6}[seed % 5u];
  stack.coloured = seed % 3u != 0u;
  const int panes = stack.layers + 1 + int(random() % 9u);
  std::vector<int> grid(25);
  std::iota(grid.begin(), grid.end(), 0);
  std::shuffle(grid.begin(), grid.end(), random);
  for (int i = 0; i < panes; ++i) {
    // Every fourth pane of some stacks lies on the height of the one before.
    const bool twin = seed % 4u == 1u && i % 4 == 3;
    const int height = grid[std::size_t(twin ? i - 1 : i)];
    Square s{0.0f, 0.0f, 2.0f, 0.5f + 0.125f * float(height), {}};
    for (int c = 0; c < 3; ++c) s.colour[c] = unit(random);
    s.colour[3] = 0.1f + 0.8f * unit(random);
    stack.glass.push_back(s);
  }
  stack.floor = seed % 2u == 0u;
  if (stack.floor)
    for (float z : {0.125f, 0.0625f})
      stack.belowFloor.push_back({0.0f, 0.0f, 2.0f, z, {0.9f, 0.2f, 0.2f, 0.5f}});
  return stack;
}

SceneTriangles stackTriangles(const Stack& stack) {
  std::vector<Square> all = stack.glass;
  if (stack.floor) all.push_back({0.0f, 0.0f, 2.0f, 0.25f, {0.5f, 0.5f, 0.5f, 1.0f}});
  all.insert(all.end(), stack.belowFloor.begin(), stack.belowFloor.end());
  // Opaque and hidden surfaces drawn between the panes, so that the lists interleave them.
  std::mt19937 random(unsigned(all.size()));
  std::shuffle(all.begin(), all.end(), random);
  return trianglesOf(all);
}

using Rgb = std::array<float, 3>;

float largestDifference(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// The panes from the light, nearest first: their distances and the light left after each.
struct Panes {
  std::vector<float> distance;
  std::vector<Rgb> after;
  // The light just behind pane i: after the last pane at its distance.
  Rgb behind(std::size_t i) const {
    while (i + 1 < distance.size() && distance[i + 1] == distance[i]) ++i;
    return after[i];
  }
};

// The least error any grouping of the panes into `layers` consecutive groups can have, each
// group stored at its first pane's distance with the light after its last: over all
// groupings, by dynamic programming. A group errs just behind its first distance (where the
// light is that after the panes there) unless all its panes lie there.
float leastGroupingError(const Panes& panes, int layers) {
  const int n = int(panes.distance.size());
  const auto groupError = [&](int i, int j) {
    if (panes.distance[std::size_t(j)] == panes.distance[std::size_t(i)]) return 0.0f;
    return largestDifference(panes.behind(std::size_t(i)), panes.after[std::size_t(j)]);
  };
  const float none = 1e30f;
  // best[g][j]: panes 0 .. j - 1 in g groups.
  std::vector<std::vector<float>> best(std::size_t(layers) + 1,
                                       std::vector<float>(std::size_t(n) + 1, none));
  best[0][0] = 0.0f;
  for (int g = 1; g <= layers; ++g)
    for (int j = 1; j <= n; ++j)
      for (int i = 0; i < j; ++i)
        if (best[std::size_t(g) - 1][std::size_t(i)] < none)
          best[std::size_t(g)][std::size_t(j)] =
              std::min(best[std::size_t(g)][std::size_t(j)],
                       std::max(best[std::size_t(g) - 1][std::size_t(i)], groupError(i, j - 1)));
  return best[std::size_t(layers)][std::size_t(n)];
}

// The panes of a stack nearest the light first: their distances (differences of heights in
// eighths: exact) and the light after each, multiplied here nearest first (SATURATE, seeds/000
// eq. 5.3, or 1 - a).
Panes panesOf(const Stack& stack) {
  std::vector<Square> sorted = stack.glass;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const Square& a, const Square& b) { return a.z > b.z; });
  Panes panes;
  Rgb light = {1.0f, 1.0f, 1.0f};
  for (const Square& s : sorted) {
    for (int c = 0; c < 3; ++c)
      light[std::size_t(c)] *=
          stack.coloured ? saturate(s.colour[c], s.colour[3]) : 1.0f - s.colour[3];
    panes.distance.push_back(4.0f - s.z);
    panes.after.push_back(light);
  }
  return panes;
}

// Every texel of the merged map against the panes: the stored layers are some of the panes,
// the light behind them all is exact, and the largest error over the panes is the one reported.
void expectTexelsWithinTheError(const Stack& stack, const Panes& panes,
                                const std::vector<MapLayerReadback>& layers, float mergeError,
                                float tolerance) {
  const std::size_t channels = stack.coloured ? 3 : 1;
  const std::set<float> paneDistances(panes.distance.begin(), panes.distance.end());
  for (std::size_t texel = 0; texel < 64; ++texel) {
    SCOPED_TRACE("texel " + std::to_string(texel));
    const auto stored = [&](std::size_t k) {
      const std::vector<float>& v = layers[k].visibility;
      return channels == 3 ? Rgb{v[texel * 3], v[texel * 3 + 1], v[texel * 3 + 2]}
                           : Rgb{v[texel], v[texel], v[texel]};
    };
    // Lokovic and Veach's property: the stored distances are some of the panes', nearest
    // first, beginning with the nearest pane.
    EXPECT_EQ(layers[0].depth[texel], panes.distance.front());
    for (std::size_t k = 0; k < std::size_t(stack.layers); ++k) {
      EXPECT_EQ(paneDistances.count(layers[k].depth[texel]), 1u) << "layer " << k;
      if (k > 0) EXPECT_GE(layers[k].depth[texel], layers[k - 1].depth[texel]);
    }
    // Behind all the panes the light is exact: every pane is in some group.
    EXPECT_LT(largestDifference(stored(std::size_t(stack.layers) - 1), panes.after.back()),
              tolerance);
    if (stack.floor) {
      // The floor closes the texel; the panes below it are no pane of any group.
      EXPECT_EQ(layers[std::size_t(stack.layers)].depth[texel], 4.0f - 0.25f);
      EXPECT_EQ(stored(std::size_t(stack.layers)), (Rgb{0.0f, 0.0f, 0.0f}));
    }
    // The map's visibility just behind each pane (lighting.glsl: the last layer nearer
    // than the point), against the light left there.
    float largest = 0.0f;
    for (std::size_t i = 0; i < panes.distance.size(); ++i) {
      const float at = panes.distance[i] + 0.0625f;  // distinct heights lie an eighth apart
      Rgb looked = {1.0f, 1.0f, 1.0f};
      for (std::size_t k = 0; k < std::size_t(stack.layers); ++k)
        if (layers[k].depth[texel] < at) looked = stored(k);
      largest = std::max(largest, largestDifference(looked, panes.behind(i)));
    }
    // The reported error is the map's largest one.
    EXPECT_NEAR(mergeError, largest, tolerance);
  }
}

TEST_F(MapLayerMergeGLTest, AStackDeeperThanItsLayersKeepsEveryPaneWithinTheReportedError) {
  auto pass = makeMapPass();
  ASSERT_TRUE(pass);
  int floors = 0, twins = 0, grey = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Stack stack = randomStack(seed);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(stack.glass.size()) +
                 " panes, maxLayers " + std::to_string(stack.layers) +
                 (stack.coloured ? ", FLOAT colours" : ", HALF grey"));
    floors += stack.floor ? 1 : 0;
    grey += stack.coloured ? 0 : 1;
    pass->uploadCasters(stackTriangles(stack));
    MapRequest request = downwards(8, stack.layers, true);
    request.mergeOverflow = true;
    request.coloured = stack.coloured;
    request.halfPrecision = !stack.coloured;
    request.colourModel =
        stack.coloured ? ShadowColourModel::Saturate : ShadowColourModel::Monochrome;
    const MapBuildResult built = pass->build(0, request);
    ASSERT_TRUE(built.fragmentLists) << built.listFailure;
    // Every texel has more panes than layers: all are merged, into as many layers as the
    // nearest panes would have taken, and the floor's closing layer.
    EXPECT_EQ(built.mergedTexels, 64u);
    const int kept = stack.layers + (stack.floor ? 1 : 0);
    ASSERT_EQ(built.layersUsed[0], kept);

    const Panes panes = panesOf(stack);
    for (std::size_t i = 1; i < panes.distance.size(); ++i)
      twins += panes.distance[i] == panes.distance[i - 1] ? 1 : 0;
    // A group's products are taken in the lists' order, not this one: a few float roundings
    // of numbers below 1, far under 1e-5. HALF rounds the stored light to 11 bits: 5e-4 of it.
    const float tolerance = stack.coloured ? 1e-5f : 1e-3f;
    // What the nearest maxLayers alone would get wrong: behind them, all the panes past them.
    const float truncationError =
        largestDifference(panes.after[std::size_t(stack.layers) - 1], panes.after.back());
    // The best grouping: the merge finds it where it sorts every pane (it sorts at least the
    // nearest 4 x maxLayers, and past them groups the rest as one); with one layer there is
    // only one grouping.
    const float least = leastGroupingError(panes, stack.layers);
    if (stack.layers == 1 || int(panes.distance.size()) <= 4 * stack.layers)
      EXPECT_NEAR(built.mergeError, least, 1e-5f);
    EXPECT_GE(built.mergeError, least - 1e-5f);
    EXPECT_LE(built.mergeError, truncationError + 1e-5f);

    std::vector<MapLayerReadback> layers(static_cast<std::size_t>(kept));
    for (int k = 0; k < kept; ++k) ASSERT_TRUE(pass->readMapLayer(0, k, layers[std::size_t(k)]));
    expectTexelsWithinTheError(stack, panes, layers, built.mergeError, tolerance);

    // Built again, as a light touched without moving: the last build's layout holds, so the
    // one sort stores and the merge writes there; the same map.
    const MapBuildResult again = pass->build(0, request);
    EXPECT_EQ(again.listSorts, 1);
    EXPECT_EQ(again.mergedTexels, built.mergedTexels);
    EXPECT_EQ(again.mergeError, built.mergeError);
    for (int k = 0; k < kept; ++k) {
      MapLayerReadback layer;
      ASSERT_TRUE(pass->readMapLayer(0, k, layer));
      EXPECT_EQ(layer.depth, layers[std::size_t(k)].depth) << "layer " << k;
      EXPECT_EQ(layer.visibility, layers[std::size_t(k)].visibility) << "layer " << k;
    }
  }
  EXPECT_EQ(floors, 10);
  EXPECT_GT(twins, 0);
  EXPECT_GT(grey, 0);
}

// A texel with as many surfaces as layers, or with an opaque surface among its nearest
// maxLayers, is stored exactly as without merging (the peel's map); the layout never changes.
void expectMergedOnlyWhereCounted(DeepShadowPass& merged, DeepShadowPass& truncated,
                                  const MapBuildResult& m, const MapBuildResult& t, int faces,
                                  int resolution) {
  ASSERT_TRUE(m.fragmentLists && t.fragmentLists);
  EXPECT_EQ(m.layersUsed, t.layersUsed);
  EXPECT_EQ(m.firstLayer, t.firstLayer);
  EXPECT_EQ(t.mergedTexels, 0u);
  std::uint64_t differing = 0;
  for (int face = 0; face < faces; ++face) {
    std::vector<bool> differs(std::size_t(resolution) * std::size_t(resolution), false);
    const std::size_t channels = 3;
    for (int k = 0; k < t.layersUsed[std::size_t(face)]; ++k) {
      MapLayerReadback a, b;
      const int layer = t.firstLayer[std::size_t(face)] + k;
      ASSERT_TRUE(merged.readMapLayer(0, layer, a));
      ASSERT_TRUE(truncated.readMapLayer(0, layer, b));
      for (std::size_t texel = 0; texel < differs.size(); ++texel) {
        bool same = a.depth[texel] == b.depth[texel];
        for (std::size_t c = 0; c < channels; ++c)
          same = same && a.visibility[texel * channels + c] == b.visibility[texel * channels + c];
        if (!same) differs[texel] = true;
      }
    }
    differing += std::uint64_t(std::count(differs.begin(), differs.end(), true));
  }
  // Every texel merged stores the light of the surfaces the nearest layers left out (none
  // clear: a fragment that lets all light through is dropped), so every one differs.
  EXPECT_EQ(differing, m.mergedTexels);
}

TEST_F(MapLayerMergeGLTest, OnlyTexelsWithMoreSurfacesThanLayersChange) {
  auto merged = makeMapPass(), truncated = makeMapPass();
  ASSERT_TRUE(merged && truncated);
  std::uint64_t mergedTexels = 0;
  for (unsigned seed : {4u, 5u}) {
    for (int layers : {1, 2, 4}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", maxLayers " + std::to_string(layers));
      // Forty squares under a light at the centre of a cube, a third of them opaque
      // (MapFragmentListsGLTest's random scenes).
      std::mt19937 random(seed);
      std::uniform_real_distribution<float> unit(0.0f, 1.0f);
      std::vector<Square> squares;
      for (int i = 0; i < 40; ++i) {
        Square s{4.0f * unit(random) - 2.0f,
                 4.0f * unit(random) - 2.0f,
                 0.2f + unit(random),
                 std::round(8.0f * (4.0f * unit(random) - 3.0f)) / 8.0f,
                 {}};
        for (int c = 0; c < 3; ++c) s.colour[c] = unit(random);
        s.colour[3] = unit(random) < 0.33f ? 1.0f : 0.1f + 0.8f * unit(random);
        squares.push_back(s);
      }
      merged->uploadCasters(trianglesOf(squares));
      truncated->uploadCasters(trianglesOf(squares));
      MapRequest request;
      request.frame = cubeFrame({0.0f, 0.0f, 1.5f}, 0.05f, 8.0f);
      request.resolution = 64;
      request.layers = layers;
      request.coloured = true;
      const MapBuildResult t = truncated->build(0, request);
      request.mergeOverflow = true;
      const MapBuildResult m = merged->build(0, request);
      expectMergedOnlyWhereCounted(*merged, *truncated, m, t, 6, request.resolution);
      mergedTexels += m.mergedTexels;
    }
  }
  EXPECT_GT(mergedTexels, 0u);
}

}  // namespace
}  // namespace ivshadow::test
