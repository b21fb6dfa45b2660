// Deep shadow maps whose texels hold more surfaces that let light through than maxLayers,
// built from fragment lists with MapRequest::mergeOverflow (SoDeepShadowLight::layerOverflow
// MERGE): random stacks of glass across one orthographic face, drawn in random order, against
// the visibility computed here from their heights and colours (seeds/000 eq. 5.3), and random
// scenes against the same lists without merging, which store the peel's map.
#include "callbacks/DeepShadowMapReadback.h"
#include "callbacks/DeepShadowPass.h"
#include "callbacks/MapFrame.h"
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

// A stack of `glass` panes across the face (so that every texel holds all of them) at
// distinct heights on a grid of eighths between 0.5 and 3.5, with an opaque floor at 0.25
// and, below the floor, panes no light reaches.
struct Stack {
  std::vector<Square> glass;  // in the order they are drawn
  bool floor = false;
  std::vector<Square> belowFloor;
  int layers = 1;
};

Stack randomStack(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Stack stack;
  stack.layers = 1 + int(seed % 4u);
  const int panes = stack.layers + 1 + int(random() % 9u);
  std::vector<int> grid(25);
  std::iota(grid.begin(), grid.end(), 0);
  std::shuffle(grid.begin(), grid.end(), random);
  for (int i = 0; i < panes; ++i) {
    Square s{0.0f, 0.0f, 2.0f, 0.5f + 0.125f * float(grid[std::size_t(i)]), {}};
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

// The least error any grouping of the panes (nearest first, `after` the light left after
// each) into `layers` consecutive groups can have, each group stored at its first pane's
// distance with the light after its last: over all groupings, by dynamic programming.
float leastGroupingError(const std::vector<Rgb>& after, int layers) {
  const int n = int(after.size());
  const auto lightAfter = [&](int i) {
    return i < 0 ? Rgb{1.0f, 1.0f, 1.0f} : after[std::size_t(i)];
  };
  // A group of panes i .. j: the point just behind pane i gets the light after pane j.
  const auto groupError = [&](int i, int j) {
    return largestDifference(lightAfter(i), lightAfter(j));
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

TEST_F(MapLayerMergeGLTest, AStackDeeperThanItsLayersKeepsEveryPaneWithinTheReportedError) {
  auto pass = makeMapPass();
  ASSERT_TRUE(pass);
  int floors = 0;
  for (unsigned seed = 1; seed <= 16; ++seed) {
    const Stack stack = randomStack(seed);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(stack.glass.size()) +
                 " panes, maxLayers " + std::to_string(stack.layers));
    floors += stack.floor ? 1 : 0;
    pass->uploadCasters(stackTriangles(stack));
    MapRequest request = downwards(8, stack.layers, true);
    request.mergeOverflow = true;
    const MapBuildResult built = pass->build(0, request);
    ASSERT_TRUE(built.fragmentLists) << built.listFailure;
    // Every texel has more panes than layers: all are merged, into as many layers as the
    // nearest panes would have taken, and the floor's closing layer.
    EXPECT_EQ(built.mergedTexels, 64u);
    const int kept = stack.layers + (stack.floor ? 1 : 0);
    ASSERT_EQ(built.layersUsed[0], kept);

    // The panes from the light: their distances (differences of heights in eighths: exact),
    // and the light left after each, multiplied here nearest first.
    std::vector<Square> panes = stack.glass;
    std::sort(panes.begin(), panes.end(),
              [](const Square& a, const Square& b) { return a.z > b.z; });
    std::vector<float> distance;
    std::vector<Rgb> after;
    Rgb light = {1.0f, 1.0f, 1.0f};
    for (const Square& s : panes) {
      for (int c = 0; c < 3; ++c) light[std::size_t(c)] *= saturate(s.colour[c], s.colour[3]);
      distance.push_back(4.0f - s.z);
      after.push_back(light);
    }
    const std::set<float> paneDistances(distance.begin(), distance.end());
    // The products of a group's panes are taken in the lists' order, not this one: a few float
    // roundings of numbers below 1, far under 1e-5.
    constexpr float kRounding = 1e-5f;
    // What the nearest maxLayers alone would get wrong: behind them, all the panes past them.
    const float truncationError =
        largestDifference(after[std::size_t(stack.layers) - 1], after.back());
    // The best grouping: the merge finds it where it sorts every pane (it sorts at least the
    // nearest 4 x maxLayers, and past them groups the rest as one); with one layer there is
    // only one grouping.
    const float least = leastGroupingError(after, stack.layers);
    if (stack.layers == 1 || int(panes.size()) <= 4 * stack.layers)
      EXPECT_NEAR(built.mergeError, least, kRounding);
    EXPECT_GE(built.mergeError, least - kRounding);

    std::vector<MapLayerReadback> layers(static_cast<std::size_t>(kept));
    for (int k = 0; k < kept; ++k) ASSERT_TRUE(pass->readMapLayer(0, k, layers[std::size_t(k)]));
    for (std::size_t texel = 0; texel < 64; ++texel) {
      SCOPED_TRACE("texel " + std::to_string(texel));
      const auto stored = [&](std::size_t k) {
        const std::vector<float>& v = layers[k].visibility;
        return Rgb{v[texel * 3], v[texel * 3 + 1], v[texel * 3 + 2]};
      };
      // Lokovic and Veach's property: the stored distances are some of the panes', nearest
      // first, beginning with the nearest pane.
      EXPECT_EQ(layers[0].depth[texel], distance.front());
      for (std::size_t k = 0; k < std::size_t(stack.layers); ++k) {
        EXPECT_EQ(paneDistances.count(layers[k].depth[texel]), 1u) << "layer " << k;
        if (k > 0) EXPECT_GT(layers[k].depth[texel], layers[k - 1].depth[texel]);
      }
      // Behind all the panes the light is exact: every pane is in some group.
      EXPECT_LT(largestDifference(stored(std::size_t(stack.layers) - 1), after.back()), kRounding);
      if (stack.floor) {
        // The floor closes the texel; the panes below it are no pane of any group.
        EXPECT_EQ(layers[std::size_t(stack.layers)].depth[texel], 4.0f - 0.25f);
        EXPECT_EQ(stored(std::size_t(stack.layers)), (Rgb{0.0f, 0.0f, 0.0f}));
      }
      // The map's visibility just behind each pane (lighting.glsl: the last layer nearer
      // than the point), against the light left there.
      float largest = 0.0f;
      for (std::size_t i = 0; i < distance.size(); ++i) {
        const float at = distance[i] + 0.0625f;  // panes lie at least an eighth apart
        Rgb looked = {1.0f, 1.0f, 1.0f};
        for (std::size_t k = 0; k < std::size_t(stack.layers); ++k)
          if (layers[k].depth[texel] < at) looked = stored(k);
        largest = std::max(largest, largestDifference(looked, after[i]));
      }
      // The reported error is the map's largest one, and at most what truncation gets wrong.
      EXPECT_NEAR(built.mergeError, largest, kRounding);
      EXPECT_LE(built.mergeError, truncationError + kRounding);
    }
  }
  EXPECT_EQ(floors, 8);
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
  EXPECT_LE(differing, m.mergedTexels);
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
