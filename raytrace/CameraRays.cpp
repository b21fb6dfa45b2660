#include "raytrace/CameraRays.h"

#include <Inventor/SbDPMatrix.h>
#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>

#include <glm/common.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivshadow {
namespace {

using Rows = double[4][4];

// The row vector (x, y, z, w) times `m`: SbDPMatrix::multVecMatrix of an SbVec4d.
glm::dvec4 times(const Rows& m, double x, double y, double z, double w) {
  return {x * m[0][0] + y * m[1][0] + z * m[2][0] + w * m[3][0],
          x * m[0][1] + y * m[1][1] + z * m[2][1] + w * m[3][1],
          x * m[0][2] + y * m[1][2] + z * m[2][2] + w * m[3][2],
          x * m[0][3] + y * m[1][3] + z * m[2][3] + w * m[3][3]};
}

// The point (x, y, z) times `m`, divided by its w: SbDPMatrix::multVecMatrix of an SbVec3d.
glm::dvec3 timesPoint(const Rows& m, double x, double y, double z) {
  const double w = x * m[0][3] + y * m[1][3] + z * m[2][3] + m[3][3];
  return {(x * m[0][0] + y * m[1][0] + z * m[2][0] + m[3][0]) / w,
          (x * m[0][1] + y * m[1][1] + z * m[2][1] + m[3][1]) / w,
          (x * m[0][2] + y * m[1][2] + z * m[2][2] + m[3][2]) / w};
}

// SbVec3d::length: the square root of the squares summed in order.
double lengthOf(const glm::dvec3& v) {
  return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

void copyRows(const SbDPMatrix& from, Rows& to) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) to[r][c] = from[r][c];
}

}  // namespace

CameraRays::CameraRays(const SbMatrix& viewing, const SbMatrix& projection, int width, int height,
                       const std::vector<glm::vec3>& positions, int viewportWidth,
                       int viewportHeight)
    : width_(width),
      height_(height),
      viewportWidth_(viewportWidth > 0 ? viewportWidth : width),
      viewportHeight_(viewportHeight > 0 ? viewportHeight : height) {
  const SbDPMatrix worldToClip = SbDPMatrix(viewing) * SbDPMatrix(projection);
  copyRows(worldToClip, worldToClip_);
  copyRows(worldToClip.inverse(), clipToWorld_);
  SbVec3f camera;
  viewing.inverse().multVecMatrix(SbVec3f(0.0f, 0.0f, 0.0f), camera);
  eye_ = glm::dvec3(double(camera[0]), double(camera[1]), double(camera[2]));
  double farthest = 0.0;
  for (const glm::vec3& p : positions)
    farthest = std::max(farthest, lengthOf(glm::dvec3(p.x, p.y, p.z) - eye_));
  reach_ = 2.0 * farthest + 1.0;
}

CameraRay CameraRays::ray(int x, int y) const {
  return rayAt((float(x) + 0.5f) / float(width_) * 2.0f - 1.0f,
               1.0f - (float(y) + 0.5f) / float(height_) * 2.0f);
}

CameraRay CameraRays::rayAt(float nx, float ny) const {
  CameraRay ray;
  ray.nx = nx;
  ray.ny = ny;
  const glm::dvec4 nearPoint = times(clipToWorld_, ray.nx, ray.ny, -1.0, 1.0);
  const glm::dvec4 farPoint = times(clipToWorld_, ray.nx, ray.ny, 1.0, 1.0);
  const glm::dvec3 origin(nearPoint.x / nearPoint.w, nearPoint.y / nearPoint.w,
                          nearPoint.z / nearPoint.w);
  // A far plane over about 1e7 times the near one rounds to infinity in the float projection
  // Coin gives GL (a near plane at 1e-11, or a far one at 1e12), and GL then draws out to
  // infinity: the ray ends past everything in the scene instead.
  // The reach counts from the eye; a ray may start behind it (an orthographic camera with a
  // negative nearDistance).
  const double reach = reach_ + glm::length(origin - eye_);
  const glm::dvec3 towardsFar = glm::dvec3(farPoint) - origin * farPoint.w;
  glm::dvec3 end = origin + towardsFar * (reach / std::max(lengthOf(towardsFar), 1e-300));
  if (farPoint.w > 0.0) {
    const glm::dvec3 farEnd(farPoint.x / farPoint.w, farPoint.y / farPoint.w,
                            farPoint.z / farPoint.w);
    if (lengthOf(farEnd - origin) < reach) end = farEnd;
  }
  ray.origin = glm::vec3(origin);
  ray.direction = glm::vec3(end - origin);
  clip(ray);
  return ray;
}

// GL draws a point whose clip coordinates have w > 0 and -w <= z <= w. Along the ray they are
// linear in t: each condition keeps an interval of it. Any camera's near plane gives [0, 1];
// a perspective camera with a negative nearDistance keeps nothing in front of it, as GL (and
// so Coin) draws nothing.
void CameraRays::clip(CameraRay& ray) const {
  const glm::vec3 end = ray.origin + ray.direction;
  const glm::dvec4 a = times(worldToClip_, ray.origin.x, ray.origin.y, ray.origin.z, 1.0);
  const glm::dvec4 b = times(worldToClip_, end.x, end.y, end.z, 1.0);
  double first = 0.0, last = 1.0;
  // value(t) = p + t (q - p) >= 0, within a rounding slack of the values' size.
  const auto keep = [&](double p, double q) {
    const double slack = 1e-6 * (std::fabs(p) + std::fabs(q));
    if (q - p > 0.0)
      first = std::max(first, (-slack - p) / (q - p));
    else if (q - p < 0.0)
      last = std::min(last, (-slack - p) / (q - p));
    else if (p < -slack)
      last = -1.0;
  };
  keep(a[3], b[3]);
  keep(a[3] + a[2], b[3] + b[2]);
  keep(a[3] - a[2], b[3] - b[2]);
  ray.first = float(first);
  ray.last = float(last);
}

float CameraRays::end(const CameraRay& ray, float limit) const {
  if (!(limit < 1.0f)) return ray.last;  // the far plane clips as in GL
  // The limit's point on this ray: its parameter, as the ray is linear in the world.
  const glm::dvec3 end = timesPoint(clipToWorld_, ray.nx, ray.ny, 2.0 * limit - 1.0);
  const glm::vec3 toEnd = glm::vec3(end) - ray.origin;
  return std::min(ray.last,
                  glm::dot(toEnd, ray.direction) / glm::dot(ray.direction, ray.direction));
}

float CameraRays::windowDepth(const CameraRay& ray, float t) const {
  const glm::vec3 p = ray.origin + t * ray.direction;
  const glm::dvec3 clip = timesPoint(worldToClip_, p.x, p.y, p.z);
  return glm::clamp(float(0.5 * clip.z + 0.5), 0.0f, 1.0f);
}

}  // namespace ivshadow

namespace ivshadow {

double CameraRays::depthSlope(const CameraRay& ray, const glm::vec3& point,
                              const glm::vec3& normal) const {
  // Window depth over a plane is affine in window coordinates: any two neighbours give its
  // slope, wherever on the plane's line they land (before the near plane or behind the eye
  // too). Only a ray along the plane, or a point at infinity, gives none.
  const auto depthOnPlane = [&](const CameraRay& r) -> double {
    const float along = glm::dot(r.direction, normal);
    if (along == 0.0f) return std::nan("");
    const float t = glm::dot(point - r.origin, normal) / along;
    const glm::vec3 p = r.origin + t * r.direction;
    const glm::dvec4 clip = times(worldToClip_, p.x, p.y, p.z, 1.0);
    return clip.w != 0.0 ? 0.5 * clip.z / clip.w + 0.5 : std::nan("");
  };
  const double here = depthOnPlane(ray);
  const double across = depthOnPlane(rayAt(ray.nx + 2.0f / float(viewportWidth_), ray.ny));
  const double up = depthOnPlane(rayAt(ray.nx, ray.ny + 2.0f / float(viewportHeight_)));
  const double slope = std::max(std::fabs(across - here), std::fabs(up - here));
  return std::isfinite(slope) ? std::min(1.0, slope) : 1.0;
}

float CameraRays::offsetDepth(const CameraRay& ray, float t, const glm::vec3& normal, float factor,
                              float units, const DepthBuffer& buffer) const {
  const float depth = windowDepth(ray, t);
  if (factor == 0.0f && units == 0.0f) return depth;
  const double slope =
      factor != 0.0f ? depthSlope(ray, ray.origin + t * ray.direction, normal) : 0.0;
  const double offset = double(factor) * slope + double(units) * buffer.resolution(depth);
  return float(std::clamp(double(depth) + offset, 0.0, 1.0));
}

std::array<glm::vec3, 2> CameraRays::footprint(const CameraRay& ray, const glm::vec3& point,
                                               const glm::vec3& normal) const {
  const auto offsetOnPlane = [&](const CameraRay& next) {
    const float along = glm::dot(next.direction, normal);
    if (along == 0.0f) return glm::vec3(std::numeric_limits<float>::infinity());
    const float t = glm::dot(point - next.origin, normal) / along;
    return next.origin + t * next.direction - point;
  };
  // The picture's own pixels: a picture traced smaller while the camera moves is stretched,
  // and its texels are taken from as far down the chain as its pixels are large.
  return {offsetOnPlane(rayAt(ray.nx + 2.0f / float(width_), ray.ny)),
          offsetOnPlane(rayAt(ray.nx, ray.ny + 2.0f / float(height_)))};
}

}  // namespace ivshadow
