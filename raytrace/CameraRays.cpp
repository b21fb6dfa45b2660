#include "raytrace/CameraRays.h"

#include <Inventor/SbDPMatrix.h>
#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>

#include <glm/common.hpp>
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivshadow {
namespace {

using Rows = double[4][4];

// The helpers of a camera ray below are forced inline: GCC called them from rayThrough, and
// their calls were about a fifth of the rays' time.

// The row vector (x, y, z, w) times `m`: SbDPMatrix::multVecMatrix of an SbVec4d.
[[gnu::always_inline]] inline glm::dvec4 times(const Rows& m, double x, double y, double z,
                                               double w) {
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

// The z and w of the point (x, y, z) times `m`, as times(m, x, y, z, 1) computes them.
[[gnu::always_inline]] inline glm::dvec2 zw(const Rows& m, double x, double y, double z) {
  return {x * m[0][2] + y * m[1][2] + z * m[2][2] + 1.0 * m[3][2],
          x * m[0][3] + y * m[1][3] + z * m[2][3] + 1.0 * m[3][3]};
}

// A homogeneous point divided by its w, as rayAt always did; an orthographic camera's w is
// exactly 1, whose quotients are the coordinates themselves, without three divisions.
[[gnu::always_inline]] inline glm::dvec3 projected(const glm::dvec4& p) {
  if (p.w == 1.0) return {p.x, p.y, p.z};
  return {p.x / p.w, p.y / p.w, p.z / p.w};
}

// SbVec3d::length: the square root of the squares summed in order.
double lengthOf(const glm::dvec3& v) {
  return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

void copyRows(const SbDPMatrix& from, Rows& to) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) to[r][c] = from[r][c];
}

// What rayThrough needs of a CameraRays (its members of those names).
struct Frustum {
  const Rows& clipToWorld;
  const Rows& worldToClip;
  const glm::dvec3& eye;
  double reach;
};

// GL draws a point whose clip coordinates have w > 0 and -w <= z <= w. Along a ray they are
// linear in t: each condition keeps an interval of it. Any camera's near plane gives [0, 1];
// a perspective camera with a negative nearDistance keeps nothing in front of it, as GL (and
// so Coin) draws nothing. The `count` rays (at most kMostClipped) are clipped together, each
// bound chosen without a branch, so that the compiler computes neighbouring rays' in one
// vector: one ray at a time, with a branch a bound, this was half the rays' time.
constexpr int kMostClipped = 16;
[[gnu::always_inline]] inline void clip(const Rows& m, CameraRay* rays, int count) {
  // Only z and w take part: those of the ray's start and end.
  double az[kMostClipped], aw[kMostClipped], bz[kMostClipped], bw[kMostClipped];
  for (int i = 0; i < count; ++i) {
    const glm::vec3 start = rays[i].origin;
    const glm::vec3 end = rays[i].origin + rays[i].direction;
    const glm::dvec2 a = zw(m, start.x, start.y, start.z);
    const glm::dvec2 b = zw(m, end.x, end.y, end.z);
    az[i] = a[0];
    aw[i] = a[1];
    bz[i] = b[0];
    bw[i] = b[1];
  }
  float firsts[kMostClipped], lasts[kMostClipped];
  for (int i = 0; i < count; ++i) {
    double first = 0.0, last = 1.0;
    // value(t) = p + t (q - p) >= 0, within a rounding slack of the values' size: where it
    // rises, t from where it crosses -slack on; where it falls, t up to there; where it is
    // flat and below, nothing.
    const auto keep = [&](double p, double q) {
      const double slack = 1e-6 * (std::fabs(p) + std::fabs(q));
      const double rise = q - p;
      const double crossing = (-slack - p) / rise;
      const bool below = p < -slack;
      first = rise > 0.0 && below && first < crossing ? crossing : first;
      last = rise < 0.0 && q < -slack && crossing < last ? crossing : last;
      last = !(rise > 0.0) && !(rise < 0.0) && below ? -1.0 : last;
    };
    keep(aw[i], bw[i]);
    keep(aw[i] + az[i], bw[i] + bz[i]);
    keep(aw[i] - az[i], bw[i] - bz[i]);
    firsts[i] = float(first);
    lasts[i] = float(last);
  }
  for (int i = 0; i < count; ++i) {
    rays[i].first = firsts[i];
    rays[i].last = lasts[i];
  }
}

// A pixel's ray from the near plane towards the far one, before clip() (CameraRays::rayAt).
// Here, not in the class: an exported member is called through the PLT and never inlined,
// and a picture's rows call this once a pixel.
[[gnu::always_inline]] inline CameraRay rayThrough(const Frustum& frustum, float nx, float ny) {
  CameraRay ray;
  ray.nx = nx;
  ray.ny = ny;
  const glm::dvec4 nearPoint = times(frustum.clipToWorld, ray.nx, ray.ny, -1.0, 1.0);
  const glm::dvec4 farPoint = times(frustum.clipToWorld, ray.nx, ray.ny, 1.0, 1.0);
  const glm::dvec3 origin = projected(nearPoint);
  // A far plane over about 1e7 times the near one rounds to infinity in the float projection
  // Coin gives GL (a near plane at 1e-11, or a far one at 1e12), and GL then draws out to
  // infinity: the ray ends past everything in the scene instead.
  // The reach counts from the eye; a ray may start behind it (an orthographic camera with a
  // negative nearDistance). A far point within the frustum's reach is within that reach
  // whatever the distance from the eye, and needs no square root: almost every camera.
  glm::dvec3 end = origin;
  bool farWithinReach = false;
  if (farPoint.w > 0.0) {
    end = projected(farPoint);
    const glm::dvec3 along = end - origin;
    farWithinReach = glm::dot(along, along) < frustum.reach * frustum.reach;
  }
  if (!farWithinReach) {
    const double reach = frustum.reach + glm::length(origin - frustum.eye);
    const glm::dvec3 towardsFar = glm::dvec3(farPoint) - origin * farPoint.w;
    const glm::dvec3 reached =
        origin + towardsFar * (reach / std::max(lengthOf(towardsFar), 1e-300));
    if (!(farPoint.w > 0.0) || !(lengthOf(end - origin) < reach)) end = reached;
  }
  ray.origin = glm::vec3(origin);
  ray.direction = glm::vec3(end - origin);
  return ray;
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

void CameraRays::rays(int x, int y, int count, CameraRay* out) const {
  const Frustum frustum{clipToWorld_, worldToClip_, eye_, reach_};
  const float ny = 1.0f - (float(y) + 0.5f) / float(height_) * 2.0f;
  for (int from = 0; from < count; from += kMostClipped) {
    const int clipped = std::min(kMostClipped, count - from);
    for (int i = from; i < from + clipped; ++i)
      out[i] = rayThrough(frustum, (float(x + i) + 0.5f) / float(width_) * 2.0f - 1.0f, ny);
    clip(worldToClip_, out + from, clipped);
  }
}

CameraRay CameraRays::rayAt(float nx, float ny) const {
  CameraRay ray = rayThrough(Frustum{clipToWorld_, worldToClip_, eye_, reach_}, nx, ny);
  clip(worldToClip_, &ray, 1);
  return ray;
}

float CameraRays::endBefore(const CameraRay& ray, float limit) const {
  // The limit's point on this ray: its parameter, as the ray is linear in the world.
  const glm::dvec3 end = timesPoint(clipToWorld_, ray.nx, ray.ny, 2.0 * limit - 1.0);
  const glm::vec3 toEnd = glm::vec3(end) - ray.origin;
  return std::min(ray.last,
                  glm::dot(toEnd, ray.direction) / glm::dot(ray.direction, ray.direction));
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

float CameraRays::offsetDepthOf(const CameraRay& ray, float t, const glm::vec3& normal,
                                float factor, float units, const DepthBuffer& buffer) const {
  const float depth = windowDepth(ray, t);
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
