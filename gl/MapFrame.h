#pragma once

#include "gl/ShaderConstants.h"
#include "ivshadow/Export.h"

#include <glm/glm.hpp>

#include <array>

namespace ivshadow {

// One face of a deep shadow map as the build draws it: the casters' coordinates to clip
// coordinates with reversed depth (distance `near` at depth 1, `far` at 0), and the distance
// the build stores, dot(p - depthOrigin, depthAxis).
struct MapFace {
  glm::mat4 viewProjection{1.0f};
  glm::vec3 depthOrigin{0.0f};
  glm::vec3 depthAxis{0.0f, 0.0f, -1.0f};
};

// How one light's map sees its casters (MapProjection): its faces for the build and, for a
// one-face map, what the lookup needs to find a point's texel and depth.
struct MapFrame {
  MapProjection projection = MapProjection::Cube;
  int faceCount = 6;
  std::array<MapFace, 6> faces{};
  // One-face maps: the casters' coordinates to (x w, y w, depth, w), x and y in [-1, 1] on the
  // face, depth as the build stores it, w the perspective divisor (1 when orthographic).
  glm::mat4 lookup{1.0f};
  // A texel's size at distance d along the axis, at resolution 1: texelScale.x * d +
  // texelScale.y (the lookup divides by the resolution). Sets the receiver's bias.
  glm::vec2 texelScale{2.0f, 0.0f};
  // The largest distance the build stores (its far plane), which sets the power of two the
  // build scales distances by to write them as depths (DeepShadowMap).
  float farDepth = 1.0f;
};

// A point light at `light`: six 90-degree faces along kFaceAxis.
IVSHADOW_INTERNAL MapFrame cubeFrame(const glm::vec3& light, float near, float far);

// A spot light at `light` looking along the unit `axis`: one square face whose half angle is
// `halfAngle` (the cone's cutOffAngle), covering the whole cone.
IVSHADOW_INTERNAL MapFrame perspectiveFrame(const glm::vec3& light, const glm::vec3& axis,
                                            float halfAngle, float near, float far);

// Light travelling along the unit `axis`: one orthographic face over the rectangle
// [low.x, high.x] x [low.y, high.y] of the plane across the axis (coordinates along
// orthographicBasis(axis)), from distance low.z to high.z along the axis.
IVSHADOW_INTERNAL MapFrame orthographicFrame(const glm::vec3& axis, const glm::vec3& low,
                                             const glm::vec3& high);

// The right and up vectors of a face looking along the unit `axis`.
void orthographicBasis(const glm::vec3& axis, glm::vec3& right, glm::vec3& up);

}  // namespace ivshadow
