// Squares of glass and opaque ones across a deep shadow map's face, for the tests of the map's
// build on its own (MapFragmentListsGLTest, MapLayerMergeGLTest): the casters as triangles,
// the face that looks down on them, and the light a surface passes.
#pragma once

#include "gl/DeepShadowPass.h"
#include "gl/MapFrame.h"
#include "scene/SceneTriangles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow::test {

// A pass of its own for each map compared (after GlContextTest made the context current).
inline std::unique_ptr<DeepShadowPass> makeMapPass() {
  std::string why;
  std::unique_ptr<DeepShadowPass> pass = DeepShadowPass::create(why);
  EXPECT_TRUE(pass) << why;
  return pass;
}

struct Square {
  float x, y, half;  // centre and half size across the light
  float z;           // height; the light looks down -z
  float colour[4];   // diffuse colour and opacity
};

inline void addTriangle(SceneTriangles& scene, const float (*corners)[3], const float colour[4]) {
  for (int i = 0; i < 3; ++i) {
    TriangleVertex v{};
    std::copy(corners[i], corners[i] + 3, v.position);
    std::copy(colour, colour + 4, v.colour);
    scene.vertices.push_back(v);
  }
  scene.shapes.push_back(std::uint32_t(scene.shapes.size()));
}

inline SceneTriangles trianglesOf(const std::vector<Square>& squares) {
  SceneTriangles scene;
  for (const Square& s : squares) {
    const float a[3][3] = {{s.x - s.half, s.y - s.half, s.z},
                           {s.x + s.half, s.y - s.half, s.z},
                           {s.x + s.half, s.y + s.half, s.z}};
    const float b[3][3] = {{s.x - s.half, s.y - s.half, s.z},
                           {s.x + s.half, s.y + s.half, s.z},
                           {s.x - s.half, s.y + s.half, s.z}};
    addTriangle(scene, a, s.colour);
    addTriangle(scene, b, s.colour);
  }
  scene.batches.push_back({-1, 0, scene.vertices.size()});
  return scene;
}

// Light passing a surface of colour c and opacity a, SATURATE (seeds/000 eq. 5.3):
// (1 - a) clamp(1 - a + c, 0, 1), per channel.
inline float saturate(float c, float a) {
  return (1.0f - a) * std::clamp(1.0f - a + c, 0.0f, 1.0f);
}

// The orthographic face over |x|, |y| <= 1 looking down from z = 4 to z = 0: a surface at
// height z is stored at distance 4 - z.
inline MapRequest downwards(int resolution, int layers, bool lists) {
  MapRequest request;
  request.frame = orthographicFrame({0.0f, 0.0f, -1.0f}, {-1.0f, -1.0f, -4.0f}, {1.0f, 1.0f, 0.0f});
  request.resolution = resolution;
  request.layers = layers;
  request.coloured = true;
  request.colourModel = ShadowColourModel::Saturate;
  request.fragmentLists = lists;
  return request;
}

}  // namespace ivshadow::test
