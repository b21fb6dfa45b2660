// The imperfect shadow maps (gl/ImperfectShadowMaps) on their own: one light facing a
// wall of points. Each texel holds the wall's distance in its direction, computed here from
// the plane; the splats leave holes where the points are sparse, and pull-push fills them.
#include "gl/ImperfectShadowMaps.h"
#include "gl/ShaderConstants.h"
#include "tests/gl/GlContextTest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ivshadow::test {
namespace {

class ImperfectShadowMapsGLTest : public GlContextTest {};

constexpr int kMapSize = 256;
constexpr float kLift = 0.01f;

// The pool: points spread evenly (Roberts' R2) over the square |x|, |y| <= 3 at z = 1.
std::vector<float> wallPoints() {
  std::vector<float> points;
  for (int k = 0; k < kIsmPointPool; ++k) {
    const double u = std::fmod(0.5 + 0.7548776662466927 * (k + 1), 1.0);
    const double v = std::fmod(0.5 + 0.5698402909980532 * (k + 1), 1.0);
    points.insert(points.end(), {float(6.0 * u - 3.0), float(6.0 * v - 3.0), 1.0f, 1.0f});
  }
  return points;
}

struct Measured {
  int texels = 0;   // texels whose direction lies within 45 degrees of the light's normal
  int holes = 0;    // ... that hold no distance
  double worst = 0.0;  // the largest relative error of the others
};

// One light at the origin facing +z: its map's texels within 45 degrees of the normal,
// against the plane's distance along each texel's centre direction (the paraboloid inverted:
// uv = l.xy / (1 + l.z), so l.z = (1 - |uv|^2) / (1 + |uv|^2)).
Measured drawAndMeasure(bool fillHoles) {
  const std::vector<float> points = wallPoints();
  const std::vector<float> light{0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 0};
  BounceMapRequest request;
  request.lights = &light;
  request.lightCount = 1;
  request.points = &points;
  request.mapSize = kMapSize;
  request.lift = kLift;
  request.fillHoles = fillHoles;
  ImperfectShadowMaps maps;
  EXPECT_EQ(maps.build(request), "");
  EXPECT_EQ(maps.tiles(), 1);
  int size = 0;
  const std::vector<float> atlas = maps.readAtlas(size);
  EXPECT_EQ(size, kMapSize);
  Measured measured;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size * 2.0 - 1.0, v = (y + 0.5) / size * 2.0 - 1.0;
      const double r2 = u * u + v * v;
      const double z = (1.0 - r2) / (1.0 + r2);
      if (z < std::cos(std::acos(-1.0) / 4.0)) continue;
      ++measured.texels;
      const float stored = atlas[std::size_t(y) * std::size_t(size) + std::size_t(x)];
      if (stored >= kIsmEmpty) {
        ++measured.holes;
        continue;
      }
      const double expected = (1.0 - kLift) / z;
      measured.worst = std::max(measured.worst, std::abs(stored / expected - 1.0));
    }
  return measured;
}

TEST_F(ImperfectShadowMapsGLTest, TexelsHoldTheWallsDistanceAndPullPushFillsTheHoles) {
  // 8192 points on 36 square units lie 0.066 apart; a texel at the centre spans 4 / 256
  // radians, 0.016 at distance 1, so 3-texel splats (0.05) leave holes between them. Measured:
  // 45 % of the 8820 texels within 45 degrees empty before pull-push, none after; every
  // distance within 2.8 % of the plane's (a splat's texels hold its point's distance, up to 1.5 texels
  // off: 0.024 along the plane at 45 degrees, 2.4 %). Bounds: holes before above 5 %, after
  // below 0.5 %; distances within 5 %, before and after (pull-push averages neighbours of
  // nearly the same distance).
  const Measured splats = drawAndMeasure(false);
  const Measured filled = drawAndMeasure(true);
  ASSERT_GT(splats.texels, 5000);
  EXPECT_GT(double(splats.holes) / splats.texels, 0.05);
  EXPECT_LT(double(filled.holes) / filled.texels, 0.005);
  EXPECT_LT(splats.worst, 0.05);
  EXPECT_LT(filled.worst, 0.05);
}

TEST_F(ImperfectShadowMapsGLTest, EachLightDrawsItsOwnTileFromItsOwnShareOfThePoints) {
  // Four lights, a 2 x 2 atlas of 64-texel tiles, the same wall at z = 1: light 0 at the
  // origin and light 3 at (0.5, -0.5, 0.2) face it (+z), light 1 at the origin faces away
  // (-z), light 2 faces along +x, tilted up by 45 degrees. Light i draws every fourth point
  // from i: lights 0 and 3 each see the wall at (1 - z - lift) / l.z along each texel within
  // 45 degrees (l.z: that texel's cosine to the normal, whatever the frame's turn about it),
  // from points no other light uses; light 1's tile, between full ones, stays empty to the
  // texel (no splat spills over a tile edge, no push reaches across); light 2 sees the wall
  // no nearer than its height allows. Distances: a 64-texel tile's texel spans 1/16 rad at
  // its centre, so a splat reaches 0.09 rad from its point, 0.13 along the wall at 45
  // degrees, where the distance changes by 9 % over that: measured 8.8 %, bound 12 %. Every
  // one of the 548 texels within 45 degrees holds a distance for lights 0, 2 and 3.
  const std::vector<float> points = wallPoints();
  const float s = std::sqrt(0.5f);
  const std::vector<float> lights{
      0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 0,           // 0: faces the wall
      0, 0, 0, 0, 0, 0, -1, 0, 1, 1, 1, 0,          // 1: faces away
      0, 0, 0, 0, s, 0, s, 0, 1, 1, 1, 0,           // 2: tilted
      0.5f, -0.5f, 0.2f, 0, 0, 0, 1, 0, 1, 1, 1, 0  // 3: faces the wall, off the axis
  };
  constexpr int kTile = 64;
  BounceMapRequest request;
  request.lights = &lights;
  request.lightCount = 4;
  request.points = &points;
  request.mapSize = kTile;
  request.lift = kLift;
  ImperfectShadowMaps maps;
  ASSERT_EQ(maps.build(request), "");
  ASSERT_EQ(maps.tiles(), 2);
  int size = 0;
  const std::vector<float> atlas = maps.readAtlas(size);
  ASSERT_EQ(size, 2 * kTile);
  const auto at = [&](int light, int x, int y) {
    const int tx = (light % 2) * kTile, ty = (light / 2) * kTile;
    return atlas[std::size_t(ty + y) * std::size_t(size) + std::size_t(tx + x)];
  };
  const float heights[4] = {0.0f, 0.0f, 0.0f, 0.2f};
  for (int light = 0; light < 4; ++light) {
    int seen = 0;
    double worst = 0.0;
    for (int y = 0; y < kTile; ++y)
      for (int x = 0; x < kTile; ++x) {
        const float stored = at(light, x, y);
        if (light == 1) {
          ASSERT_EQ(stored, kIsmEmpty) << x << ", " << y;
          continue;
        }
        const double u = (x + 0.5) / kTile * 2.0 - 1.0, v = (y + 0.5) / kTile * 2.0 - 1.0;
        const double r2 = u * u + v * v;
        const double cosine = (1.0 - r2) / (1.0 + r2);
        if (cosine < std::cos(std::acos(-1.0) / 4.0) || stored >= kIsmEmpty) continue;
        ++seen;
        if (light == 2) {
          EXPECT_GE(stored, 0.95 * (1.0 - kLift * s));
          continue;
        }
        const double expected = (1.0 - heights[light] - kLift) / cosine;
        worst = std::max(worst, std::abs(stored / expected - 1.0));
      }
    if (light == 1) continue;
    EXPECT_EQ(seen, 548) << "light " << light;
    EXPECT_LT(worst, 0.12) << "light " << light;
  }
}

TEST_F(ImperfectShadowMapsGLTest, WithoutPointsNothingHidesTheLight) {
  // No opaque caster: the map is drawn empty, every texel kIsmEmpty.
  const std::vector<float> none;
  const std::vector<float> light{0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 0};
  BounceMapRequest request;
  request.lights = &light;
  request.lightCount = 1;
  request.points = &none;
  request.mapSize = 16;
  ImperfectShadowMaps maps;
  ASSERT_EQ(maps.build(request), "");
  int size = 0;
  for (float texel : maps.readAtlas(size)) ASSERT_EQ(texel, kIsmEmpty);
  EXPECT_EQ(size, 16);
}

}  // namespace
}  // namespace ivshadow::test
