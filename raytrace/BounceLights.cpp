#include "raytrace/BounceLights.h"

#include "raytrace/CasterScene.h"
#include "raytrace/SurfaceOptics.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ivshadow {
namespace {

constexpr float kPi = 3.14159265358979f;
// The golden angle: consecutive points of a Fibonacci spiral turn by it, which spreads any
// number of them evenly over a sphere or a cap.
constexpr float kGoldenAngle = 2.39996323f;
// At most this many samples per light asked for: a light that mostly misses the casters
// (a point light among a few small ones) places fewer lights rather than trace without end.
constexpr int kMaxBounceSampling = 16;

// Point i of n of Roberts' R2 sequence in the unit square: evenly spread for every n, where
// a grid needs a square number.
void r2(int i, float& u, float& v) {
  constexpr double a1 = 0.7548776662466927, a2 = 0.5698402909980532;  // 1 / plastic number
  u = float(std::fmod(0.5 + a1 * double(i + 1), 1.0));
  v = float(std::fmod(0.5 + a2 * double(i + 1), 1.0));
}

// Two unit vectors that make an orthonormal frame with the unit vector n.
void across(const glm::vec3& n, glm::vec3& t1, glm::vec3& t2) {
  const glm::vec3 along = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t1 = glm::normalize(glm::cross(n, along));
  t2 = glm::cross(n, t1);
}

// One sample's ray from a light into the casters and the area (a directional light's) or
// solid angle its sample stands for, times the light's intensity along it.
struct Sample {
  glm::vec3 origin, direction;
  float measure;  // area across a directional light, else solid angle
  float spot;     // the spot light's falloff along the ray (1 for the others)
};

float attenuationAt(const BounceSource& source, float distance) {
  if (source.kind == LightKind::Directional) return 1.0f;
  const float a = source.attenuation.x + source.attenuation.y * distance +
                  source.attenuation.z * distance * distance;
  return a > 0.0f ? 1.0f / a : 0.0f;
}

std::vector<Sample> samplesOf(const BounceSource& source, int count, const SbBox3f& bounds) {
  std::vector<Sample> samples;
  if (count <= 0) return samples;
  samples.reserve(std::size_t(count));
  if (source.kind == LightKind::Directional) {
    // The rectangle across the light that covers the casters' box, beyond the box's far side
    // towards the light.
    const glm::vec3 towards = glm::normalize(source.position);
    glm::vec3 t1, t2;
    across(towards, t1, t2);
    const SbVec3f low = bounds.getMin(), high = bounds.getMax();
    float lo1 = std::numeric_limits<float>::max(), hi1 = -lo1, lo2 = lo1, hi2 = -lo1, top = -lo1;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p(corner & 1 ? high[0] : low[0], corner & 2 ? high[1] : low[1],
                        corner & 4 ? high[2] : low[2]);
      lo1 = std::min(lo1, glm::dot(p, t1));
      hi1 = std::max(hi1, glm::dot(p, t1));
      lo2 = std::min(lo2, glm::dot(p, t2));
      hi2 = std::max(hi2, glm::dot(p, t2));
      top = std::max(top, glm::dot(p, towards));
    }
    const float reach = top + 1.0f + 0.01f * (hi1 - lo1 + hi2 - lo2);
    const float area = (hi1 - lo1) * (hi2 - lo2);
    for (int i = 0; i < count; ++i) {
      float u, v;
      r2(i, u, v);
      const glm::vec3 origin =
          (lo1 + u * (hi1 - lo1)) * t1 + (lo2 + v * (hi2 - lo2)) * t2 + reach * towards;
      samples.push_back({origin, -towards, area / float(count), 1.0f});
    }
    return samples;
  }
  // The directions that can meet a caster: the cap about the casters' bounding sphere when
  // the light is outside it (a point light beside a model sends most of its sphere to the
  // sky), else the spot light's cone or the whole sphere; a spot light's cone where it is
  // the narrower. Each sample stands for an equal share of the cap's solid angle.
  const bool spot = source.kind == LightKind::Spot;
  const float cosCutoff = spot ? std::clamp(source.cosCutoff, -1.0f, 1.0f) : -1.0f;
  const glm::vec3 spotAxis = spot ? glm::normalize(source.axis) : glm::vec3(0, 0, 1);
  glm::vec3 axis = spotAxis;
  float capCos = cosCutoff;
  const SbVec3f centre = bounds.getCenter();
  const glm::vec3 toCentre = glm::vec3(centre[0], centre[1], centre[2]) - source.position;
  const float distance = glm::length(toCentre);
  const float radius = 0.5f * (bounds.getMax() - bounds.getMin()).length();
  if (distance > radius) {
    const float boundsCos = std::sqrt(std::max(0.0f, 1.0f - (radius / distance) * (radius / distance)));
    if (boundsCos > capCos) {
      axis = toCentre / distance;
      capCos = boundsCos;
    }
  }
  glm::vec3 t1, t2;
  across(axis, t1, t2);
  const float solidAngle = 2.0f * kPi * (1.0f - capCos);
  for (int i = 0; i < count; ++i) {
    // A Fibonacci spiral over the cap cos(theta) in [capCos, 1]: equal solid angle per point.
    const float z = 1.0f - (float(i) + 0.5f) / float(count) * (1.0f - capCos);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = kGoldenAngle * float(i);
    const glm::vec3 direction = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + z * axis;
    float falloff = 1.0f;
    if (spot) {
      const float c = glm::dot(direction, spotAxis);
      falloff = c < cosCutoff ? 0.0f : std::pow(std::max(c, 0.0f), source.spotExponent);
    }
    samples.push_back({source.position, direction, solidAngle / float(count), falloff});
  }
  return samples;
}

// The lights `samples` samples of `source` place, appended to `out`; how many it placed.
int placeFrom(const CasterScene& casters, const BounceSource& source, int samples,
              const SbBox3f& bounds, std::vector<BounceLight>& out) {
  int placed = 0;
  for (const Sample& sample : samplesOf(source, samples, bounds)) {
    const CasterScene::SurfaceHit hit = casters.firstSurface(
        sample.origin, sample.direction, std::numeric_limits<float>::infinity(), source.model);
    if (!hit.hit) continue;
    glm::vec3 normal = casters.geometricNormal(hit.primitive);
    // The side the light falls on reflects it (a one-sided surface lit from behind too).
    float cosine = -glm::dot(normal, sample.direction);
    if (cosine < 0.0f) {
      normal = -normal;
      cosine = -cosine;
    }
    if (!(cosine > 0.0f)) continue;
    const glm::vec3 kd = glm::vec3(casters.surfaceColour(hit.primitive, hit.u, hit.v));
    // The area the sample stands for on the surface: across the light, or the solid angle at
    // the distance reached, over the cosine; the direct diffuse term kd I cos att there times
    // it leaves the cosine out.
    const bool directional = source.kind == LightKind::Directional;
    const float spread = directional ? sample.measure : sample.measure * hit.t * hit.t;
    const glm::vec3 flux = glm::clamp(kd, 0.0f, 1.0f) * source.colour * hit.through *
                           (attenuationAt(source, hit.t) * sample.spot * spread);
    if (!(glm::dot(flux, glm::vec3(1.0f)) > 0.0f)) continue;
    out.push_back({sample.origin + hit.t * sample.direction, normal, flux, spread / cosine / kPi});
    ++placed;
  }
  return placed;
}

}  // namespace

BounceLights placeBounceLights(const CasterScene& casters, const std::vector<BounceSource>& sources,
                               int count) {
  BounceLights result;
  const SbBox3f& bounds = casters.triangles().bounds;
  if (sources.empty() || count <= 0 || bounds.isEmpty()) return result;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const BounceSource& source = sources[s];
    // The lights shared out evenly; the first ones take what the division leaves.
    const int share = count / int(sources.size()) + (int(s) < count % int(sources.size()) ? 1 : 0);
    if (share <= 0) continue;
    const std::size_t before = result.lights.size();
    int samples = share;
    const int placed = placeFrom(casters, source, samples, bounds, result.lights);
    // Samples that met nothing placed nothing: as many more as the share that landed says
    // give about `share` lights (at most kMaxBounceSampling times the share, for a light that
    // mostly misses), placed anew from the finer pattern.
    if (placed > 0 && placed < share) {
      samples = int(std::min<std::int64_t>(std::int64_t(share) * kMaxBounceSampling,
                                           (std::int64_t(share) * share + placed - 1) / placed));
      result.lights.resize(before);
      placeFrom(casters, source, samples, bounds, result.lights);
    }
    result.samples += samples;
  }
  return result;
}

std::vector<float> opaquePointPool(const CasterScene& casters, int count) {
  const SceneTriangles& triangles = casters.triangles();
  std::vector<double> cumulative;
  std::vector<unsigned int> opaque;
  double total = 0.0;
  for (unsigned int i = 0; i < triangles.triangleCount(); ++i) {
    if (!isOpaque(casters.surfaceColour(i, 1.0f / 3.0f, 1.0f / 3.0f).a)) continue;
    const TriangleVertex* v = casters.corners(i);
    const glm::vec3 a(v[0].position[0], v[0].position[1], v[0].position[2]);
    const glm::vec3 b(v[1].position[0], v[1].position[1], v[1].position[2]);
    const glm::vec3 c(v[2].position[0], v[2].position[1], v[2].position[2]);
    const double area = 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    if (!(area > 0.0)) continue;
    total += area;
    cumulative.push_back(total);
    opaque.push_back(i);
  }
  std::vector<float> points;
  if (opaque.empty() || count <= 0) return points;
  points.reserve(std::size_t(count) * 4);
  for (int k = 0; k < count; ++k) {
    const double at = (double(k) + 0.5) / double(count) * total;
    const std::size_t index = std::size_t(
        std::lower_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin());
    const TriangleVertex* v = casters.corners(opaque[std::min(index, opaque.size() - 1)]);
    float u, w;
    r2(k, u, w);
    if (u + w > 1.0f) {  // the square's other half folds onto the triangle
      u = 1.0f - u;
      w = 1.0f - w;
    }
    for (int axis = 0; axis < 3; ++axis)
      points.push_back((1.0f - u - w) * v[0].position[axis] + u * v[1].position[axis] +
                       w * v[2].position[axis]);
    points.push_back(1.0f);
  }
  return points;
}

glm::vec3 gatherBounce(const BounceLights& lights, const glm::vec3& x, const glm::vec3& n,
                       const CasterScene* visibility) {
  glm::vec3 sum(0.0f);
  for (const BounceLight& light : lights.lights) {
    const glm::vec3 towards = light.position - x;
    const float squared = glm::dot(towards, towards);
    if (!(squared > 0.0f)) continue;
    const glm::vec3 w = towards / std::sqrt(squared);
    const float receiving = glm::dot(n, w), sending = -glm::dot(light.normal, w);
    if (!(receiving > 0.0f) || !(sending > 0.0f)) continue;
    float seen = 1.0f;
    if (visibility != nullptr) {
      // Stop short of the light's own surface, which the ray would otherwise meet at its end.
      const glm::vec3 end = light.position - 1e-3f * std::sqrt(light.discRadiusSquared) * w;
      seen = visibility->transmittance(x, n, end, ShadowColourModel::Monochrome).x;
    }
    sum += light.flux * (receiving * sending * seen / (squared + light.discRadiusSquared));
  }
  return sum / kPi;
}

}  // namespace ivshadow
