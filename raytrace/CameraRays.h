#pragma once

#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

class SbMatrix;

namespace ivshadow {

// A pixel's camera ray: from the near plane (t = 0) towards the far plane (t = 1), of which GL
// draws what lies in [first, last].
struct CameraRay {
  float nx = 0.0f, ny = 0.0f;  // the pixel's centre in normalised device coordinates
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f};
  float first = 0.0f;
  float last = 1.0f;
};

// The camera rays of a width x height picture seen through `viewing` and `projection` (Coin's
// matrices, as GL draws with them), and where along them window depths lie. In doubles: a near
// plane at 1e-11 or a far one 1e12 times as far lost the rays in a float inverse.
class IVSHADOW_INTERNAL CameraRays {
 public:
  // `positions`: the scene's triangle corners, which every ray must be able to reach.
  // `viewportWidth` x `viewportHeight`: the pixels GL draws the picture over (a picture traced
  // at a lower resolution is stretched over more); 0: the picture's own.
  CameraRays(const SbMatrix& viewing, const SbMatrix& projection, int width, int height,
             const std::vector<glm::vec3>& positions, int viewportWidth = 0,
             int viewportHeight = 0);

  CameraRay ray(int x, int y) const;
  // The rays of `count` neighbouring pixels of row y from column x on, into `out`: ray(x + i,
  // y) each, computed inline (an exported member is called through the PLT, a call a ray).
  void rays(int x, int y, int count, CameraRay* out) const;
  // The ray through normalised device coordinates (nx, ny).
  CameraRay rayAt(float nx, float ny) const;
  // Where a ray ending at window depth `limit` ends: its parameter (1 and above: the far plane).
  // Inline, as windowDepth and offsetDepth without an offset: each is asked once a pixel, and
  // an exported member is otherwise called through the PLT.
  float end(const CameraRay& ray, float limit) const {
    if (!(limit < 1.0f)) return ray.last;  // the far plane clips as in GL
    return endBefore(ray, limit);
  }
  // The window depth of the point at parameter `t` along a ray.
  float windowDepth(const CameraRay& ray, float t) const {
    const glm::vec3 p = ray.origin + t * ray.direction;
    // The z of SbDPMatrix::multVecMatrix alone, in its order: one division where the point
    // needs three.
    const Rows& m = worldToClip_;
    const double x = p.x, y = p.y, z = p.z;
    const double w = x * m[0][3] + y * m[1][3] + z * m[2][3] + m[3][3];
    const double depth = (x * m[0][2] + y * m[1][2] + z * m[2][2] + m[3][2]) / w;
    const float window = float(0.5 * depth + 0.5);
    return window < 0.0f ? 0.0f : window > 1.0f ? 1.0f : window;
  }
  // The window depth at parameter `t` of a ray meeting a face of geometric normal `normal`,
  // offset as GL offsets the face under SoPolygonOffset in `buffer` (`factor` times its depth
  // slope plus `units` times the buffer's resolution; both 0: none), so that lines drawn on it
  // after the picture stay in front of it (a cube's lower edges vanished under TRACER).
  float offsetDepth(const CameraRay& ray, float t, const glm::vec3& normal, float factor,
                    float units, const DepthBuffer& buffer) const {
    if (factor == 0.0f && units == 0.0f) return windowDepth(ray, t);
    return offsetDepthOf(ray, t, normal, factor, units, buffer);
  }
  // Where the next pixel's rays, across and up, meet the plane through `point` with normal
  // `normal`, less `point`: the pixel's footprint on the surface (ray differentials), from
  // which GL's texture level of detail follows. Infinite where a neighbour's ray runs along
  // the plane.
  std::array<glm::vec3, 2> footprint(const CameraRay& ray, const glm::vec3& point,
                                     const glm::vec3& normal) const;

 private:
  // end() before the far plane.
  float endBefore(const CameraRay& ray, float limit) const;
  // offsetDepth() with an offset.
  float offsetDepthOf(const CameraRay& ray, float t, const glm::vec3& normal, float factor,
                      float units, const DepthBuffer& buffer) const;
  // How fast the window depth of the plane through `point` with normal `normal` changes from
  // `ray`'s viewport pixel to the next, across or up, the larger (GL's m in glPolygonOffset);
  // 1, the whole depth range, where the plane is seen edge-on.
  double depthSlope(const CameraRay& ray, const glm::vec3& point, const glm::vec3& normal) const;

  // A matrix as Coin stores it (row vectors times the matrix), its products written out as
  // SbDPMatrix::multVecMatrix computes them, in the same order: a call into Coin for each of a
  // pixel's four products was a quarter of a traced frame.
  using Rows = double[4][4];

  int width_;
  int height_;
  int viewportWidth_;
  int viewportHeight_;
  glm::dvec3 eye_{0.0};
  Rows worldToClip_{};
  Rows clipToWorld_{};
  double reach_ = 1.0;  // farther than every triangle from the camera, with room
};

}  // namespace ivshadow
