// The transparent shadow volumes' faces (raytrace/ShadowVolumes) against an answer computed
// without them: for points about the casters, the z-fail count along a ray from the point
// away from an eye (faces crossed facing away from the eye count +weight, towards it
// -weight) must equal the sum of log transmittance of the caster triangles the segment from
// the point to the light crosses, found by intersecting that segment with each triangle.
#include "raytrace/ShadowVolumes.h"
#include "scene/SceneTriangles.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <vector>

namespace ivshadow {
namespace {

using dvec3 = glm::dvec3;

// Whether the segment or ray from `origin` along `direction` (t in (0, limit)) crosses the
// triangle (a, b, c); Moeller-Trumbore in doubles.
std::optional<double> crossing(const dvec3& origin, const dvec3& direction, const dvec3& a,
                               const dvec3& b, const dvec3& c, double limit) {
  const dvec3 e1 = b - a, e2 = c - a;
  const dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return std::nullopt;
  const dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) / det;
  if (t <= 0.0 || t >= limit) return std::nullopt;
  return t;
}

struct Caster {
  glm::vec3 a, b, c;
  glm::vec4 colour;  // rgb, opacity
};

SceneTriangles trianglesOf(const std::vector<Caster>& casters) {
  SceneTriangles scene;
  for (const Caster& caster : casters)
    for (const glm::vec3& p : {caster.a, caster.b, caster.c}) {
      TriangleVertex v{};
      for (int i = 0; i < 3; ++i) v.position[i] = p[i];
      for (int i = 0; i < 4; ++i) v.colour[i] = caster.colour[i];
      scene.vertices.push_back(v);
    }
  scene.batches.push_back(TriangleBatch{-1, 0, scene.vertices.size()});
  scene.shapes.assign(casters.size(), 0);
  return scene;
}

// The answer from the casters alone (monochrome model: a surface of opacity a lets 1 - a
// through, per channel the same).
double expectedLog(const std::vector<Caster>& casters, const dvec3& point, const dvec3& light,
                   bool directional) {
  const dvec3 direction = directional ? light : light - point;
  const double limit = directional ? 1e300 : 1.0;
  double sum = 0.0;
  for (const Caster& caster : casters)
    if (crossing(point, direction, dvec3(caster.a), dvec3(caster.b), dvec3(caster.c), limit)) {
      const double through = 1.0 - double(caster.colour.a);
      sum += std::log(std::max(through, double(kMinTransmittance)));
    }
  return sum;
}

// The z-fail count through the volumes' faces, along the whole ray.
double countedLog(const std::vector<VolumeVertex>& faces, const dvec3& point, const dvec3& eye) {
  const dvec3 away = point - eye;
  double sum = 0.0;
  for (std::size_t i = 0; i + 2 < faces.size(); i += 3) {
    dvec3 p[3];
    for (int k = 0; k < 3; ++k) {
      const float* f = faces[i + std::size_t(k)].position;
      EXPECT_EQ(f[3], 1.0f);
      p[k] = dvec3(f[0], f[1], f[2]);
    }
    if (!crossing(point, away, p[0], p[1], p[2], 1e300)) continue;
    const dvec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double sign = glm::dot(normal, away) > 0.0 ? 1.0 : -1.0;  // leaving: +
    sum += sign * double(faces[i].weight[0]);
  }
  return sum;
}

// A closed axis-aligned box of 12 triangles, wound outwards, its corners shared.
std::vector<Caster> box(const glm::vec3& low, const glm::vec3& high, const glm::vec4& colour) {
  const auto corner = [&](int i) {
    return glm::vec3(i & 1 ? high.x : low.x, i & 2 ? high.y : low.y, i & 4 ? high.z : low.z);
  };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Caster> out;
  for (const auto& q : quads) {
    out.push_back({corner(q[0]), corner(q[1]), corner(q[2]), colour});
    out.push_back({corner(q[0]), corner(q[2]), corner(q[3]), colour});
  }
  return out;
}

void expectCountsMatch(const std::vector<Caster>& casters, const glm::vec3& light,
                       bool directional) {
  const SceneTriangles scene = trianglesOf(casters);
  const ShadowVolumes volumes(scene, ShadowColourModel::Monochrome);
  std::vector<VolumeVertex> faces;
  // Receivers anywhere in the box the points are drawn from.
  volumes.build(light, directional, {-3, -3, -4}, {3, 3, 2}, faces);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> place(-3.0, 3.0);
  const dvec3 eyes[2] = {dvec3(0.3, 0.2, 9.0), dvec3(-7.0, 4.0, -2.0)};
  int shadowed = 0;
  for (int i = 0; i < 400; ++i) {
    const dvec3 point(place(random), place(random), place(random) - 1.0);
    const double expected = expectedLog(casters, point, dvec3(light), directional);
    if (expected < 0.0) ++shadowed;
    for (const dvec3& eye : eyes) {
      // Float weights summed in doubles: a few float roundings of terms up to log(2^-24).
      EXPECT_NEAR(countedLog(faces, point, eye), expected, 1e-4)
          << "point " << point.x << " " << point.y << " " << point.z;
    }
  }
  // The points must reach the shadows, or the test shows nothing.
  EXPECT_GT(shadowed, 20);
}

const glm::vec4 kHalf(1.0f, 1.0f, 1.0f, 0.5f);

TEST(ShadowVolumes, ClosedBoxFromAPointLight) {
  expectCountsMatch(box({-1, -1, -1}, {1, 1, 0.5f}, kHalf), {0.4f, 0.7f, 4.0f}, false);
}

TEST(ShadowVolumes, ClosedBoxFromADirectionalLight) {
  expectCountsMatch(box({-1, -1, -1}, {1, 1, 0.5f}, kHalf),
                    glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f)), true);
}

TEST(ShadowVolumes, OpenAndInconsistentlyWoundMeshes) {
  std::vector<Caster> casters = box({-1, -1, -1}, {1, 1, 0.5f}, kHalf);
  casters.erase(casters.begin() + 2, casters.begin() + 4);  // the top is open
  std::swap(casters[5].b, casters[5].c);                    // one face wound inwards
  expectCountsMatch(casters, {0.4f, 0.7f, 4.0f}, false);
}

TEST(ShadowVolumes, StackedPanesOfDifferentOpacityAndAnOpaqueOneSharingEdges) {
  std::vector<Caster> casters;
  const glm::vec4 opacities[3] = {{1, 1, 1, 0.3f}, {1, 1, 1, 0.8f}, {1, 1, 1, 1.0f}};
  for (int i = 0; i < 3; ++i) {
    const float z = 0.5f - 0.6f * float(i);
    // Two triangles of different opacity share the pane's diagonal.
    casters.push_back({{-1, -1, z}, {1, -1, z}, {1, 1, z}, opacities[i]});
    casters.push_back({{-1, -1, z}, {1, 1, z}, {-1, 1, z}, opacities[(i + 1) % 3]});
  }
  expectCountsMatch(casters, {0.2f, -0.3f, 3.0f}, false);
  expectCountsMatch(casters, glm::normalize(glm::vec3(0.5f, 0.1f, 1.0f)), true);
}

TEST(ShadowVolumes, ClosedBoxKeepsOnlyItsSilhouetteEdges) {
  // A light off every axis: three faces towards it, three away, six silhouette edges. Each
  // of the 12
  // triangles gives two caps (6 vertices) and each silhouette edge one quad (6 vertices).
  const SceneTriangles scene = trianglesOf(box({-1, -1, -1}, {1, 1, 1}, kHalf));
  const ShadowVolumes volumes(scene, ShadowColourModel::Monochrome);
  EXPECT_EQ(volumes.edgeCount(), 18u);  // 12 box edges and the 6 face diagonals
  std::vector<VolumeVertex> faces;
  volumes.build({5.0f, 4.0f, 3.0f}, false, {-1, -1, -1}, {1, 1, 1}, faces);
  EXPECT_EQ(faces.size(), 12u * 6u + 6u * 6u);
  // And every silhouette quad carries both surfaces a ray through the box meets.
  for (std::size_t i = 12u * 6u; i < faces.size(); ++i)
    EXPECT_FLOAT_EQ(std::abs(faces[i].weight[0]), -2.0f * std::log(0.5f)) << i;
}

TEST(ShadowVolumes, EachChannelCarriesItsOwnTransmittance) {
  // Saturate model (seeds/000 eq. 5.3): a surface of colour c and opacity a passes
  // (1 - a) clamp(1 - a + c, 0, 1) per channel. Red glass of opacity 0.6: red 0.4, green and
  // blue 0.4 * 0.4 = 0.16. A cyan pane of opacity 0.3 behind it: red 0.7 * 0.7, green and
  // blue 0.7. Counted per channel at points behind both.
  const std::vector<Caster> casters = {
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {1, 0, 0, 0.6f}},
      {{-1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, {1, 0, 0, 0.6f}},
      {{-1, -1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}, {0, 1, 1, 0.3f}},
      {{-1, -1, 0.5f}, {1, 1, 0.5f}, {-1, 1, 0.5f}, {0, 1, 1, 0.3f}}};
  const ShadowVolumes volumes(trianglesOf(casters), ShadowColourModel::Saturate);
  std::vector<VolumeVertex> faces;
  volumes.build({0.0f, 0.0f, 3.0f}, false, {-3, -3, -1}, {3, 3, 3}, faces);
  const double red = std::log(0.4) + std::log(0.7 * 0.7);
  const double cyan = std::log(0.16) + std::log(0.7);
  for (const dvec3& point : {dvec3(0.1, 0.2, 0.0), dvec3(-0.3, 0.4, -0.5)}) {
    double sum[3] = {0.0, 0.0, 0.0};
    const dvec3 eye(0.5, 0.3, 9.0), away = point - eye;
    for (std::size_t i = 0; i + 2 < faces.size(); i += 3) {
      dvec3 p[3];
      for (int k = 0; k < 3; ++k) {
        const float* f = faces[i + std::size_t(k)].position;
        p[k] = dvec3(f[0], f[1], f[2]);
      }
      if (!crossing(point, away, p[0], p[1], p[2], 1e300)) continue;
      const double sign = glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), away) > 0.0 ? 1.0 : -1.0;
      for (int c = 0; c < 3; ++c) sum[c] += sign * double(faces[i].weight[c]);
    }
    EXPECT_NEAR(sum[0], red, 1e-5);
    EXPECT_NEAR(sum[1], cyan, 1e-5);
    EXPECT_NEAR(sum[2], cyan, 1e-5);
  }
}

TEST(ShadowVolumes, ClearTrianglesCastNoVolumeAndColoursAreAveragedAndCounted) {
  std::vector<Caster> casters = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1, 0.0f}}};
  SceneTriangles scene = trianglesOf(casters);
  ShadowVolumes clear(scene, ShadowColourModel::Monochrome);
  EXPECT_EQ(clear.triangleCount(), 0u);
  // One corner half opaque, the others clear: the volume has their mean, 1/6.
  scene.vertices[0].colour[3] = 0.5f;
  ShadowVolumes mixed(scene, ShadowColourModel::Monochrome);
  EXPECT_EQ(mixed.approximatedTriangles(), 1u);
  std::vector<VolumeVertex> faces;
  mixed.build({0.2f, 0.2f, 2.0f}, false, {0, 0, 0}, {1, 1, 0}, faces);
  ASSERT_FALSE(faces.empty());
  EXPECT_FLOAT_EQ(faces[0].weight[0], std::log(1.0f - 0.5f / 3.0f));
}

// Every edge of the faces, with the weights of the faces on it summed by the direction they
// run it in, is zero: the faces close (a volume's boundary has no rim), which is what lets a
// rasteriser count each pixel's crossings without cracks. Edges compare corner bits, as the
// rasteriser's shared vertices do.
void expectFacesClose(const std::vector<VolumeVertex>& faces) {
  std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, double> rim;
  for (std::size_t i = 0; i + 2 < faces.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      const float* a = faces[i + std::size_t(k)].position;
      const float* b = faces[i + std::size_t((k + 1) % 3)].position;
      std::array<float, 3> pa{a[0], a[1], a[2]}, pb{b[0], b[1], b[2]};
      const double w = faces[i].weight[0];
      if (pa < pb)
        rim[{pa, pb}] += w;
      else
        rim[{pb, pa}] -= w;
    }
  int open = 0;
  for (const auto& [edge, sum] : rim)
    if (std::abs(sum) > 1e-5) ++open;
  EXPECT_EQ(open, 0) << "of " << rim.size() << " edges";
}

TEST(ShadowVolumes, AWallAroundAWindowWithTJunctionsCountsAndCloses) {
  // A tall quad beside a short one below a window pane and a short one above it: the short
  // quads' corners lie on the tall quad's edge (x = 1), a T-junction. Each triangle's volume
  // closes over its own corners, so the faces close and count without splitting the edge.
  const auto quad = [](float x0, float x1, float z0, float z1, float opacity) {
    const glm::vec4 colour(1.0f, 1.0f, 1.0f, opacity);
    return std::vector<Caster>{{{x0, 0, z0}, {x1, 0, z0}, {x1, 0, z1}, colour},
                               {{x0, 0, z0}, {x1, 0, z1}, {x0, 0, z1}, colour}};
  };
  std::vector<Caster> casters;
  for (const auto& q : {quad(0, 1, 0, 4, 1.0f), quad(1, 3, 0, 1, 1.0f), quad(1, 3, 1, 3, 0.5f),
                        quad(1, 3, 3, 4, 1.0f)})
    casters.insert(casters.end(), q.begin(), q.end());
  const SceneTriangles scene = trianglesOf(casters);
  const ShadowVolumes volumes(scene, ShadowColourModel::Monochrome);
  for (bool directional : {false, true}) {
    std::vector<VolumeVertex> faces;
    const glm::vec3 light =
        directional ? glm::normalize(glm::vec3(0.2f, -1.0f, 0.5f)) : glm::vec3(1.5f, -4.0f, 2.0f);
    volumes.build(light, directional, {-2, -2, -2}, {5, 5, 6}, faces);
    expectFacesClose(faces);
  }
  expectCountsMatch(casters, {1.5f, -4.0f, 2.0f}, false);
}

TEST(ShadowVolumes, EveryCasterSetsFacesThatClose) {
  std::vector<Caster> casters = box({-1, -1, -1}, {1, 1, 0.5f}, kHalf);
  casters.erase(casters.begin() + 2, casters.begin() + 4);
  std::swap(casters[5].b, casters[5].c);
  std::vector<VolumeVertex> faces;
  ShadowVolumes(trianglesOf(casters), ShadowColourModel::Monochrome)
      .build({0.4f, 0.7f, 4.0f}, false, {-3, -3, -3}, {3, 3, 3}, faces);
  expectFacesClose(faces);
}

}  // namespace
}  // namespace ivshadow
