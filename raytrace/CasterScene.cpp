#include "raytrace/CasterScene.h"

#include "raytrace/RayRange.h"

#include "raytrace/SurfaceOptics.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace ivshadow {
namespace {

// The running product of one shadow ray, found by the ray's id.
struct ShadowLane {
  ShadowColourModel model = ShadowColourModel::Monochrome;
  glm::vec3 visibility{1.0f};
  // Surfaces already counted on this ray (shape, ray parameter); kept per thread so that no
  // ray allocates.
  std::vector<std::pair<std::uint32_t, float>>* seen = nullptr;
};

// Embree hands the filter function the context it was given; the rays' running products
// travel in it, one lane per ray of a packet (a single ray is lane 0).
struct ShadowRayContext : RTCIntersectContext {
  const CasterScene* scene = nullptr;
  ShadowLane* lanes = nullptr;
  // firstSurface(): transparent hits (ray parameter, transmittance) are collected here and
  // passed over, opaque ones accepted; Embree then keeps the nearest opaque one.
  std::vector<std::pair<float, glm::vec3>>* collected = nullptr;
};

bool alreadySeen(ShadowLane& lane, std::uint32_t shape, float t) {
  for (const auto& [seenShape, seenT] : *lane.seen)
    if (seenShape == shape && sameSurface(seenT, t)) return true;
  lane.seen->emplace_back(shape, t);
  return false;
}

void shadowFilter(const RTCFilterFunctionNArguments* args) {
  auto& context = *static_cast<ShadowRayContext*>(args->context);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    ShadowLane& lane = context.lanes[RTCRayN_id(args->ray, args->N, i)];
    const unsigned int primitive = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    const float t = RTCRayN_tfar(args->ray, args->N, i);
    const glm::vec4 colour = context.scene->surfaceColour(primitive, u, v);
    // A fully clear surface casts nothing, and a surface met before is not met again.
    if (colour.a <= 0.0f || alreadySeen(lane, context.scene->shapeOf(primitive), t)) {
      args->valid[i] = 0;
      continue;
    }
    if (isOpaque(colour.a)) {
      if (context.collected != nullptr) continue;  // a candidate for the nearest opaque surface
      lane.visibility = glm::vec3(0.0f);
      continue;  // accepted: the ray is blocked and traversal stops
    }
    const glm::vec3 through = transmittance(glm::clamp(colour, 0.0f, 1.0f), lane.model);
    if (context.collected != nullptr)
      context.collected->emplace_back(t, through);
    else
      lane.visibility *= through;
    args->valid[i] = 0;  // let light through: look for the next surface
  }
}

// The casters' bounds where they are traced: callers may have moved the vertices (the
// reference into world space) after the extraction measured them.
void measureBounds(SceneTriangles& casters) {
  casters.bounds.makeEmpty();
  for (const TriangleVertex& vertex : casters.vertices)
    casters.bounds.extendBy(SbVec3f(vertex.position));
}

}  // namespace

void CasterScene::measureFlatColours() {
  const std::size_t count = casters_.triangleCount();
  flatColour_.assign(count, glm::vec4(kNotFlat));
  for (std::size_t i = 0; i < count; ++i) {
    if (triangleTexture_[i] >= 0) continue;
    const TriangleVertex* vertex = &casters_.vertices[i * 3];
    if (std::equal(vertex[0].colour, vertex[0].colour + 4, vertex[1].colour) &&
        std::equal(vertex[0].colour, vertex[0].colour + 4, vertex[2].colour))
      flatColour_[i] = glm::vec4(vertex[0].colour[0], vertex[0].colour[1], vertex[0].colour[2],
                                 vertex[0].colour[3]);
  }
}

std::unique_ptr<CasterScene> CasterScene::build(RTCDevice device, SceneTriangles casters,
                                                std::string& error) {
  std::unique_ptr<CasterScene> result(new CasterScene);
  result->casters_ = std::move(casters);
  measureBounds(result->casters_);
  const SceneTriangles& triangles = result->casters_;
  result->triangleTexture_.resize(triangles.triangleCount(), -1);
  for (const TriangleBatch& batch : triangles.batches)
    std::fill_n(result->triangleTexture_.begin() + std::ptrdiff_t(batch.firstVertex / 3),
                batch.vertexCount / 3, batch.texture);
  result->measureFlatColours();

  result->packetWidth_ = nativePacketWidth(device);
  result->scene_ = buildTriangleScene(
      device, triangles.triangleCount(),
      [&triangles](std::size_t i) { return triangles.vertices[i].position; }, shadowFilter, error);
  if (!result->scene_) return nullptr;
  return result;
}

CasterScene::~CasterScene() = default;

CasterScene::Update CasterScene::update(const SceneTriangles& casters) {
  const std::size_t count = casters.triangleCount();
  if (count == 0 || count != casters_.triangleCount() || casters.shapes != casters_.shapes)
    return Update::Rebuild;
  bool moved = false;
  for (std::size_t i = 0; i < count * 3 && !moved; ++i)
    for (int k = 0; k < 3; ++k)
      moved = moved || casters.vertices[i].position[k] != casters_.vertices[i].position[k];
  casters_ = casters;
  measureBounds(casters_);
  for (const TriangleBatch& batch : casters_.batches)
    std::fill_n(triangleTexture_.begin() + std::ptrdiff_t(batch.firstVertex / 3),
                batch.vertexCount / 3, batch.texture);
  measureFlatColours();
  if (!moved) return Update::Colours;
  RTCGeometry geometry = rtcGetGeometry(scene_.get(), 0);
  auto* positions =
      static_cast<float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0));
  for (std::size_t i = 0; i < count * 3; ++i)
    for (std::size_t k = 0; k < 3; ++k) positions[i * 3 + k] = casters_.vertices[i].position[k];
  rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(geometry);
  rtcCommitScene(scene_.get());
  return Update::Refit;
}

glm::vec4 CasterScene::surfaceColour(unsigned int primitive, float u, float v) const {
  const glm::vec4& flat = flatColour_[primitive];
  if (flat.a != kNotFlat) return flat;
  const TriangleVertex* vertex = &casters_.vertices[std::size_t(primitive) * 3];
  glm::vec4 colours[3];
  glm::vec2 texCoords[3];
  for (int i = 0; i < 3; ++i) {
    colours[i] = glm::vec4(vertex[i].colour[0], vertex[i].colour[1], vertex[i].colour[2],
                           vertex[i].colour[3]);
    texCoords[i] = glm::vec2(vertex[i].texCoord[0], vertex[i].texCoord[1]);
  }
  const int texture = triangleTexture_[primitive];
  const TextureImage* image = texture >= 0 ? &casters_.textures[std::size_t(texture)] : nullptr;
  const SurfaceSample sample = sampleSurface(colours, texCoords, image, u, v);
  return texturedColour(sample.colour, sample.texel, image);
}

glm::vec3 CasterScene::pastCasters(const glm::vec3& from, const glm::vec3& towards) const {
  // A point beyond every caster along the ray: farther than the casters' farthest corner is
  // from `from` (no caster lies past it), and the ray then is an ordinary finite one.
  const SbVec3f low = casters_.bounds.getMin(), high = casters_.bounds.getMax();
  float reach = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float d = std::max(std::fabs(from[i] - low[i]), std::fabs(from[i] - high[i]));
    reach += d * d;
  }
  const float length = 2.0f * std::sqrt(reach) + 1.0f;
  return from + glm::normalize(towards) * length;
}

glm::vec3 CasterScene::transmittanceTowards(const glm::vec3& from, const glm::vec3& normal,
                                            const glm::vec3& towards,
                                            ShadowColourModel model) const {
  if (casters_.bounds.isEmpty()) return glm::vec3(1.0f);
  return transmittance(from, normal, pastCasters(from, towards), model);
}

bool CasterScene::shadowRay(const glm::vec3& from, const glm::vec3& normal, const glm::vec3& to,
                            ShadowRay& ray) const {
  // Float positions carry a relative error near 1e-7; stepping 1e-5 of the larger of the
  // point's magnitude and the ray's length off the surface clears it by two orders. A light
  // far outside the casters (1e20 away) needs no more than their extent: past it no caster
  // can be met, and a step of 1e-5 of the light's distance would jump over all of them.
  const glm::dvec3 toLight = glm::dvec3(to) - glm::dvec3(from);
  const double length = glm::length(toLight);
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  const float magnitude = std::max({std::fabs(from.x), std::fabs(from.y), std::fabs(from.z)});
  const float extent =
      casters_.bounds.isEmpty()
          ? float(length)
          : std::min(float(length), (casters_.bounds.getMax() - casters_.bounds.getMin()).length());
  const float offset = 1e-5f * std::max(magnitude, extent);
  const float side = glm::dot(normal, to - from) >= 0.0f ? 1.0f : -1.0f;
  const float normalLength = glm::length(normal);
  ray.origin = normalLength > 0.0f ? from + normal * (side * offset / normalLength) : from;
  // Embree takes only rays whose origin and direction lie within about 1.8e18 (its
  // ray.valid() assertion aborted the process for a light at 1e20): a unit direction and the
  // distance as tfar keep every finite light within that.
  const glm::dvec3 towards = glm::dvec3(to) - glm::dvec3(ray.origin);
  const double distance = glm::length(towards);
  if (!(distance > 0.0)) return false;
  ray.direction = glm::vec3(towards / distance);
  if (!embreeTakesRay(ray.origin, ray.direction)) return false;
  ray.tnear = float(std::min(double(offset), 0.5 * distance));
  ray.tfar = float(std::min(distance, double(std::numeric_limits<float>::max())));  // the light
  return true;
}

glm::vec3 CasterScene::transmittance(const glm::vec3& from, const glm::vec3& normal,
                                     const glm::vec3& to, ShadowColourModel model) const {
  if (casters_.vertices.empty()) return glm::vec3(1.0f);
  ShadowRay shadow;
  if (!shadowRay(from, normal, to, shadow)) return glm::vec3(1.0f);
  thread_local std::vector<std::pair<std::uint32_t, float>> seen;
  seen.clear();
  ShadowLane lane;
  lane.model = model;
  lane.seen = &seen;
  ShadowRayContext context;
  rtcInitIntersectContext(&context);
  context.scene = this;
  context.lanes = &lane;
  RTCRay ray{};  // id 0: the one lane
  ray.org_x = shadow.origin.x;
  ray.org_y = shadow.origin.y;
  ray.org_z = shadow.origin.z;
  ray.dir_x = shadow.direction.x;
  ray.dir_y = shadow.direction.y;
  ray.dir_z = shadow.direction.z;
  ray.tnear = shadow.tnear;
  ray.tfar = shadow.tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  rtcOccluded1(scene_.get(), &context, &ray);
  // Embree marks a blocked ray with tfar = -inf (an accepted hit: an opaque surface).
  if (ray.tfar < 0.0f) return glm::vec3(0.0f);
  return lane.visibility;
}

template <int Width, typename Packet>
void CasterScene::tracePackets(const Query* queries, std::size_t count, glm::vec3* out,
                               void (*occluded)(const int*, RTCScene, RTCIntersectContext*,
                                                Packet*)) const {
  thread_local std::vector<std::pair<std::uint32_t, float>> seen[Width];
  ShadowLane lanes[Width];
  ShadowRayContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  context.scene = this;
  context.lanes = lanes;
  std::size_t next = 0;
  while (next < count) {
    Packet packet{};
    alignas(64) int valid[Width] = {};  // Embree reads the mask as one vector
    std::size_t answer[Width];
    int used = 0;
    for (; used < Width && next < count; ++next) {
      const Query& query = queries[next];
      const glm::vec3 to = query.directional ? pastCasters(query.from, query.to) : query.to;
      ShadowRay shadow;
      if (!shadowRay(query.from, query.normal, to, shadow)) {
        out[next] = glm::vec3(1.0f);
        continue;
      }
      seen[used].clear();
      lanes[used] = ShadowLane{query.model, glm::vec3(1.0f), &seen[used]};
      packet.org_x[used] = shadow.origin.x;
      packet.org_y[used] = shadow.origin.y;
      packet.org_z[used] = shadow.origin.z;
      packet.dir_x[used] = shadow.direction.x;
      packet.dir_y[used] = shadow.direction.y;
      packet.dir_z[used] = shadow.direction.z;
      packet.tnear[used] = shadow.tnear;
      packet.tfar[used] = shadow.tfar;
      packet.mask[used] = 0xFFFFFFFFu;
      packet.id[used] = unsigned(used);
      valid[used] = -1;
      answer[used] = next;
      ++used;
    }
    if (used == 0) break;
    occluded(valid, scene_.get(), &context, &packet);
    for (int i = 0; i < used; ++i)
      out[answer[i]] = packet.tfar[i] < 0.0f ? glm::vec3(0.0f) : lanes[i].visibility;
  }
}

void CasterScene::transmittances(const Query* queries, std::size_t count, glm::vec3* out) const {
  if (casters_.vertices.empty()) {
    std::fill_n(out, count, glm::vec3(1.0f));
    return;
  }
  switch (packetWidth_) {
    case 16:
      return tracePackets<16, RTCRay16>(queries, count, out, rtcOccluded16);
    case 8:
      return tracePackets<8, RTCRay8>(queries, count, out, rtcOccluded8);
    case 4:
      return tracePackets<4, RTCRay4>(queries, count, out, rtcOccluded4);
    default:
      for (std::size_t i = 0; i < count; ++i) {
        const Query& q = queries[i];
        out[i] = q.directional ? transmittanceTowards(q.from, q.normal, q.to, q.model)
                               : transmittance(q.from, q.normal, q.to, q.model);
      }
  }
}

CasterScene::SurfaceHit CasterScene::firstSurface(const glm::vec3& origin,
                                                  const glm::vec3& direction, float tfar,
                                                  ShadowColourModel model) const {
  SurfaceHit result;
  if (casters_.vertices.empty() || !embreeTakesRay(origin, direction)) return result;
  thread_local std::vector<std::pair<std::uint32_t, float>> seen;
  thread_local std::vector<std::pair<float, glm::vec3>> collected;
  seen.clear();
  collected.clear();
  ShadowLane lane;
  lane.model = model;
  lane.seen = &seen;
  ShadowRayContext context;
  rtcInitIntersectContext(&context);
  context.scene = this;
  context.lanes = &lane;
  context.collected = &collected;
  RTCRayHit rayHit = singleRay(origin, direction, 0.0f, tfar);
  rtcIntersect1(scene_.get(), &context, &rayHit);
  result.hit = rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  if (result.hit) {
    result.t = rayHit.ray.tfar;
    result.primitive = rayHit.hit.primID;
    result.u = rayHit.hit.u;
    result.v = rayHit.hit.v;
  }
  // Embree visits candidates in no particular order: only the glass before the opaque
  // surface filters the light that reaches it.
  for (const auto& [t, through] : collected)
    if (!result.hit || t < result.t) result.through *= through;
  return result;
}

glm::vec3 CasterScene::geometricNormal(unsigned int primitive) const {
  const TriangleVertex* v = corners(primitive);
  const glm::vec3 a(v[0].position[0], v[0].position[1], v[0].position[2]);
  const glm::vec3 b(v[1].position[0], v[1].position[1], v[1].position[2]);
  const glm::vec3 c(v[2].position[0], v[2].position[1], v[2].position[2]);
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

}  // namespace ivshadow
