#include "nodes/CameraRays.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3d.h>
#include <Inventor/SbVec3f.h>
#include <Inventor/SbVec4d.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivshadow {

CameraRays::CameraRays(const SbMatrix& viewing, const SbMatrix& projection, int width, int height,
                       const std::vector<glm::vec3>& positions, int viewportWidth,
                       int viewportHeight)
    : width_(width),
      height_(height),
      viewportWidth_(viewportWidth > 0 ? viewportWidth : width),
      viewportHeight_(viewportHeight > 0 ? viewportHeight : height),
      worldToClip_(SbDPMatrix(viewing) * SbDPMatrix(projection)),
      clipToWorld_(worldToClip_.inverse()) {
  SbVec3f camera;
  viewing.inverse().multVecMatrix(SbVec3f(0.0f, 0.0f, 0.0f), camera);
  const SbVec3d eye(camera);
  eye_ = glm::dvec3(eye[0], eye[1], eye[2]);
  double farthest = 0.0;
  for (const glm::vec3& p : positions)
    farthest = std::max(farthest, (SbVec3d(p.x, p.y, p.z) - eye).length());
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
  SbVec4d nearPoint, farPoint;
  clipToWorld_.multVecMatrix(SbVec4d(ray.nx, ray.ny, -1.0, 1.0), nearPoint);
  clipToWorld_.multVecMatrix(SbVec4d(ray.nx, ray.ny, 1.0, 1.0), farPoint);
  SbVec3d origin;
  nearPoint.getReal(origin);
  // A far plane over about 1e7 times the near one rounds to infinity in the float projection
  // Coin gives GL (a near plane at 1e-11, or a far one at 1e12), and GL then draws out to
  // infinity: the ray ends past everything in the scene instead.
  // The reach counts from the eye; a ray may start behind it (an orthographic camera with a
  // negative nearDistance).
  const double reach = reach_ + glm::length(glm::dvec3(origin[0], origin[1], origin[2]) - eye_);
  const SbVec3d towardsFar = SbVec3d(farPoint[0], farPoint[1], farPoint[2]) - origin * farPoint[3];
  SbVec3d end = origin + towardsFar * (reach / std::max(towardsFar.length(), 1e-300));
  if (farPoint[3] > 0.0) {
    SbVec3d farEnd;
    farPoint.getReal(farEnd);
    if ((farEnd - origin).length() < reach) end = farEnd;
  }
  ray.origin = glm::vec3(origin[0], origin[1], origin[2]);
  ray.direction = glm::vec3(end[0] - origin[0], end[1] - origin[1], end[2] - origin[2]);
  clip(ray);
  return ray;
}

// GL draws a point whose clip coordinates have w > 0 and -w <= z <= w. Along the ray they are
// linear in t: each condition keeps an interval of it. Any camera's near plane gives [0, 1];
// a perspective camera with a negative nearDistance keeps nothing in front of it, as GL (and
// so Coin) draws nothing.
void CameraRays::clip(CameraRay& ray) const {
  const glm::vec3 end = ray.origin + ray.direction;
  SbVec4d a, b;
  worldToClip_.multVecMatrix(SbVec4d(ray.origin.x, ray.origin.y, ray.origin.z, 1.0), a);
  worldToClip_.multVecMatrix(SbVec4d(end.x, end.y, end.z, 1.0), b);
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
  SbVec3d end;
  clipToWorld_.multVecMatrix(SbVec3d(ray.nx, ray.ny, 2.0 * limit - 1.0), end);
  const glm::vec3 toEnd = glm::vec3(end[0], end[1], end[2]) - ray.origin;
  return std::min(ray.last,
                  glm::dot(toEnd, ray.direction) / glm::dot(ray.direction, ray.direction));
}

float CameraRays::windowDepth(const CameraRay& ray, float t) const {
  SbVec3d clip;
  const glm::vec3 p = ray.origin + t * ray.direction;
  worldToClip_.multVecMatrix(SbVec3d(p.x, p.y, p.z), clip);
  return glm::clamp(float(0.5 * clip[2] + 0.5), 0.0f, 1.0f);
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
    SbVec4d clip;
    const glm::vec3 p = r.origin + t * r.direction;
    worldToClip_.multVecMatrix(SbVec4d(p.x, p.y, p.z, 1.0), clip);
    return clip[3] != 0.0 ? 0.5 * clip[2] / clip[3] + 0.5 : std::nan("");
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

}  // namespace ivshadow
