#include "gl/MapFrame.h"

#include <algorithm>
#include <cmath>

namespace ivshadow {
namespace {

glm::vec3 faceVector(const FaceVectors& vectors, int face) {
  const auto& v = vectors[std::size_t(face)];
  return {v[0], v[1], v[2]};
}

// A view from `eye` looking along `axis` with `right` and `up` spanning the image.
glm::mat4 viewMatrix(const glm::vec3& eye, const glm::vec3& axis, const glm::vec3& right,
                     const glm::vec3& up) {
  glm::mat4 view(1.0f);
  for (int column = 0; column < 3; ++column) {
    view[column][0] = right[column];
    view[column][1] = up[column];
    view[column][2] = -axis[column];
  }
  view[3] = glm::vec4(-glm::dot(right, eye), -glm::dot(up, eye), glm::dot(axis, eye), 1.0f);
  return view;
}

// A square perspective projection of half angle atan(tanHalf) that maps distance `near` to
// depth 1 and `far` to 0 (reversed depth with glClipControl's zero-to-one range:
// floating-point depth then keeps its precision over near/far ratios of 1e6 and more).
glm::mat4 perspectiveProjection(float tanHalf, float near, float far) {
  glm::mat4 projection(0.0f);
  projection[0][0] = 1.0f / tanHalf;
  projection[1][1] = 1.0f / tanHalf;
  projection[2][2] = near / (far - near);
  projection[2][3] = -1.0f;
  projection[3][2] = near * far / (far - near);
  return projection;
}

// The rows of a one-face lookup: (right . (p - o)) / sx, (up . (p - o)) / sy, axis . (p - o)
// and, perspective, axis . (p - o) again as w (else 1).
glm::mat4 lookupMatrix(const glm::vec3& origin, const glm::vec3& axis, const glm::vec3& right,
                       const glm::vec3& up, float sx, float sy, bool perspective) {
  glm::mat4 m(0.0f);
  const glm::vec3 rows[3] = {right / sx, up / sy, axis};
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) m[column][row] = rows[row][column];
    m[3][row] = -glm::dot(rows[row], origin);
  }
  if (perspective) {
    for (int column = 0; column < 3; ++column) m[column][3] = axis[column];
    m[3][3] = -glm::dot(axis, origin);
  } else {
    m[3][3] = 1.0f;
  }
  return m;
}

}  // namespace

void orthographicBasis(const glm::vec3& axis, glm::vec3& right, glm::vec3& up) {
  // Any vector not along the axis gives a right vector; the smallest component's axis is
  // the farthest from parallel.
  const glm::vec3 a = glm::abs(axis);
  const glm::vec3 helper = a.x <= a.y && a.x <= a.z ? glm::vec3(1, 0, 0)
                           : a.y <= a.z             ? glm::vec3(0, 1, 0)
                                                    : glm::vec3(0, 0, 1);
  right = glm::normalize(glm::cross(axis, helper));
  up = glm::cross(-axis, right);
}

MapFrame cubeFrame(const glm::vec3& light, float near, float far) {
  MapFrame frame;
  frame.projection = MapProjection::Cube;
  frame.faceCount = 6;
  const glm::mat4 projection = perspectiveProjection(1.0f, near, far);
  for (int face = 0; face < 6; ++face) {
    MapFace& f = frame.faces[std::size_t(face)];
    f.depthOrigin = light;
    f.depthAxis = faceVector(kFaceAxis, face);
    f.viewProjection = projection * viewMatrix(light, f.depthAxis, faceVector(kFaceRight, face),
                                               faceVector(kFaceUp, face));
  }
  frame.texelScale = {2.0f, 0.0f};
  frame.farDepth = far;
  return frame;
}

MapFrame perspectiveFrame(const glm::vec3& light, const glm::vec3& axis, float halfAngle,
                          float near, float far) {
  MapFrame frame;
  frame.projection = MapProjection::Perspective;
  frame.faceCount = 1;
  glm::vec3 right, up;
  orthographicBasis(axis, right, up);
  const float tanHalf = std::tan(halfAngle);
  MapFace& f = frame.faces[0];
  f.depthOrigin = light;
  f.depthAxis = axis;
  f.viewProjection = perspectiveProjection(tanHalf, near, far) * viewMatrix(light, axis, right, up);
  frame.lookup = lookupMatrix(light, axis, right, up, tanHalf, tanHalf, true);
  frame.texelScale = {2.0f * tanHalf, 0.0f};
  frame.farDepth = far;
  return frame;
}

MapFrame orthographicFrame(const glm::vec3& axis, const glm::vec3& low, const glm::vec3& high) {
  MapFrame frame;
  frame.projection = MapProjection::Orthographic;
  frame.faceCount = 1;
  glm::vec3 right, up;
  orthographicBasis(axis, right, up);
  // A rectangle or depth range of no extent (one flat caster seen edge-on, a single point)
  // still makes an invertible projection.
  const glm::vec3 extent = glm::max(high - low, glm::vec3(1e-6f * (1.0f + glm::length(high))));
  const float halfX = 0.5f * extent.x, halfY = 0.5f * extent.y;
  const float depth = extent.z;
  const glm::vec3 origin = (low.x + halfX) * right + (low.y + halfY) * up + low.z * axis;
  MapFace& f = frame.faces[0];
  f.depthOrigin = origin;
  f.depthAxis = axis;
  // (x, y) to [-1, 1]; distance 0 along the axis to depth 1 and `depth` to 0.
  glm::mat4 projection(1.0f);
  projection[0][0] = 1.0f / halfX;
  projection[1][1] = 1.0f / halfY;
  projection[2][2] = 1.0f / depth;
  projection[3][2] = 1.0f;
  f.viewProjection = projection * viewMatrix(origin, axis, right, up);
  frame.lookup = lookupMatrix(origin, axis, right, up, halfX, halfY, false);
  frame.texelScale = {0.0f, 2.0f * std::max(halfX, halfY)};
  frame.farDepth = depth;
  return frame;
}

}  // namespace ivshadow
