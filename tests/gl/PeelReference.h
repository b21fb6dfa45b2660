#pragma once

#include "image/Image.h"
#include "scene/SceneTriangles.h"

#include <array>
#include <optional>
#include <vector>

class SoNode;

namespace ivshadow::test {

// The exact picture of unlit (BASE_COLOR) transparent surfaces seen through an orthographic
// camera looking down -z, computed on the CPU without GL: per pixel, a ray through the
// pixel's centre meets every triangle (SoCallbackAction's triangles, so the same ones Coin
// draws), the hits are sorted by depth and composited front to back,
// C += T a c, T *= 1 - a, over a black background; an opaque hit ends the ray.
class PeelReference {
 public:
  // `height`: the camera's view height in scene units, centred on the origin.
  PeelReference(SoNode* root, double viewHeight, int size);

  // Layers kept per pixel, counting transparent hits from the front: the first `front` and
  // the last `back` (as a capped DUAL pass count keeps them); nullopt keeps all.
  struct Keep {
    int front = 1 << 30;
    int back = 0;
  };
  // The composited colour at pixel (px, py), 0..255 per channel, or nothing when an edge
  // passes within 0.02 pixel of its centre (the rasterizer and the ray may round it apart).
  std::optional<std::array<double, 3>> pixel(int px, int py, Keep keep) const;
  std::optional<std::array<double, 3>> pixel(int px, int py) const { return pixel(px, py, Keep{}); }
  // The largest number of transparent hits along any pixel's ray.
  int depthComplexity() const;

 private:
  struct Hit {
    double depth;
    std::array<double, 4> colour;
  };
  std::vector<Hit> hits(double x, double y) const;
  std::array<double, 3> composite(std::vector<Hit> hits, Keep keep) const;

  SceneTriangles triangles_;
  double viewHeight_;
  int size_;
};

}  // namespace ivshadow::test
