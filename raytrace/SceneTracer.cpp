#include "raytrace/SceneTracer.h"

#include "ivshadow/SoTransparentShadowGroup.h"
#include "raytrace/CameraFilter.h"
#include "raytrace/CameraRays.h"
#include "raytrace/CasterScene.h"
#include "raytrace/CastingLight.h"
#include "raytrace/EmbreeHandles.h"
#include "raytrace/HitOrder.h"
#include "raytrace/LightEquation.h"
#include "raytrace/ParallelRows.h"
#include "raytrace/RayRange.h"
#include "raytrace/RowShading.h"
#include "raytrace/SceneExtraction.h"
#include "raytrace/SurfaceOptics.h"
#include "raytrace/TextureFootprint.h"
#include "scene/SceneTriangles.h"
#include "scene/ShadowTypes.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>

#include <cstring>
#include <functional>
#include <limits>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace ivshadow {
namespace {

using detail::CameraRayContext;
using detail::dropFrom;
using detail::Extraction;
using detail::Group;
using detail::imageOf;
using detail::inDepthOrder;
using detail::Light;
using detail::LightType;
using detail::Material;
using detail::PendingShade;
using detail::RowShading;
using detail::ShadowTerm;
using detail::toGlm;
using detail::Triangle;

using Hit = SurfacesMet::Hit;

// Camera rays traced together, as many as a packet holds.
constexpr int kMaxPacket = 16;

struct RayCounts {
  std::size_t shadow = 0;
  std::size_t bounce = 0;
};

class Tracer {
 public:
  Tracer(const Extraction& data, RTCScene scene, int packetWidth, const SbMatrix& viewing,
         const SbMatrix& projection, const TraceOptions& options)
      : data_(data),
        scene_(scene),
        packetWidth_(std::min(packetWidth, kMaxPacket)),
        options_(options),
        viewing_(viewing),
        cameraRays_(viewing, projection, options.width, options.height, data.positions,
                    options.viewportWidth, options.viewportHeight) {
    SbVec3f back;
    viewing.inverse().multDirMatrix(SbVec3f(0.0f, 0.0f, 1.0f), back);
    back.normalize();
    viewDirection_ = toGlm(back);
    // Which lights each group's casters shadow and in which colour model: resolved once a
    // trace, not at every shaded point (the model reads the light's and the group's fields).
    casting_.assign(data.groups.size() * data.lights.size(), kNotCasting);
    for (std::size_t g = 0; g < data.groups.size(); ++g) {
      const Group& group = data.groups[g];
      if (!group.casters) continue;
      for (int index : group.casting)
        casting_[g * data.lights.size() + std::size_t(index)] = int(castingColourModel(
            *data.lights[std::size_t(index)].node,
            *static_cast<const SoTransparentShadowGroup*>(group.node), group.casters->coloured()));
    }
  }

  const CameraRays& cameraRays() const { return cameraRays_; }

  // The surfaces along `count` (at most kMaxPacket) neighbouring camera rays, rays[i]'s into
  // hits[i] in exact depth order, ending at limits[i], the window depth where the ray ends (1:
  // the far plane), or at the nearest opaque surface; depths[i] is that surface's window depth,
  // or the limit where there is none. Traced as one packet where Embree has them: neighbouring
  // camera rays walk the same nodes of the tree.
  void visible(const CameraRay* rays, const float* limits, int count, std::vector<Hit>* hits,
               float* depths) const {
    switch (packetWidth_) {
      case 16:
        return visibleTogether<16, RTCRayHit16>(rays, limits, count, hits, depths, rtcIntersect16);
      case 8:
        for (int i = 0; i < count; i += 8)
          visibleTogether<8, RTCRayHit8>(rays + i, limits + i, std::min(8, count - i), hits + i,
                                         depths + i, rtcIntersect8);
        return;
      case 4:
        for (int i = 0; i < count; i += 4)
          visibleTogether<4, RTCRayHit4>(rays + i, limits + i, std::min(4, count - i), hits + i,
                                         depths + i, rtcIntersect4);
        return;
      default:
        for (int i = 0; i < count; ++i) {
          const CameraRay& ray = rays[i];
          const bool opaque = surfacesAlong(ray.origin, ray.direction, ray.first,
                                            cameraRays_.end(ray, limits[i]), hits[i]);
          depths[i] = opaque ? opaqueDepth(ray, hits[i].back()) : limits[i];
        }
    }
  }

  // The `count` surfaces `hits` met along `ray`, front to back, shaded up to their shadows
  // into `row` as one more pixel, as far as light gets through them. A pixel that asks no
  // shadow ray is composited at once and its surfaces dropped, not kept in the row for
  // resolve() to read back.
  void gather(const CameraRay& ray, const Hit* hits, std::size_t count, float depth,
              RayCounts& rays, RowShading& row) const {
    const std::size_t begin = row.shades.size();
    const std::size_t termsBefore = row.terms.size();
    float transmitted = 1.0f;
    for (std::size_t i = 0; i < count; ++i) {
      const Hit& hit = hits[i];
      const Triangle& tri = data_.triangles[hit.primitive];
      if (metBefore(hits, i)) continue;
      const glm::vec3 position = ray.origin + hit.t * ray.direction;
      // Most surfaces have no texture: no call for its level of detail.
      const float lod =
          tri.texture >= 0 ? levelOfDetail(data_, cameraRays_, ray, tri, position) : 0.0f;
      const PendingShade& shade = prepare(tri, hit, position, ray.direction, lod, rays, row);
      transmitted *= 1.0f - shade.opacity;
      if (transmitted <= 0.0f) break;
    }
    const bool waits = row.terms.size() != termsBefore;
    row.composites.push_back(waits ? glm::vec4(0.0f) : composite(row, begin, row.shades.size()));
    row.composited.push_back(waits ? 0 : 1);
    if (!waits) row.shades.resize(begin);
    row.pixelEnds.push_back(std::uint32_t(row.shades.size()));
    row.depths.push_back(depth);
  }

  // Pixel `pixel` of `row`, its shadow rays answered: its surfaces finished and composited
  // (TracedPixels: premultiplied rgb, the transmittance left).
  glm::vec4 resolve(const RowShading& row, std::size_t pixel) const {
    return row.composited[pixel] != 0
               ? row.composites[pixel]
               : composite(row, pixel > 0 ? row.pixelEnds[pixel - 1] : 0, row.pixelEnds[pixel]);
  }

 private:
  // row.shades[begin, end) finished (their shadow rays answered, if any) and composited front
  // to back: premultiplied rgb, and the transmittance left.
  glm::vec4 composite(const RowShading& row, std::size_t begin, std::size_t end) const {
    glm::vec3 colour(0.0f);
    float transmitted = 1.0f;
    for (std::size_t i = begin; i < end; ++i) {
      const PendingShade& shade = row.shades[i];
      colour +=
          transmitted * shade.opacity * finish(shade, row, i > 0 ? row.shades[i - 1].termsEnd : 0u);
      transmitted *= 1.0f - shade.opacity;
    }
    return glm::vec4(colour, std::max(transmitted, 0.0f));
  }

  // The window depth GL tests what it draws after the picture against (CameraRays).
  float opaqueDepth(const CameraRay& ray, const Hit& hit) const {
    const Triangle& tri = data_.triangles[hit.primitive];
    return cameraRays_.offsetDepth(ray, hit.t, tri.geometricNormal, tri.offsetFactor,
                                   tri.offsetUnits, options_.depthBuffer);
  }

  template <int Width, typename Packet>
  void visibleTogether(const CameraRay* rays, const float* limits, int count,
                       std::vector<Hit>* hits, float* depths,
                       void (*intersect)(const int*, RTCScene, RTCIntersectContext*,
                                         Packet*)) const {
    // Lanes past `count` are zeroed, as Embree loads whole vectors; a full packet (every one
    // but a row's last) has every field Embree reads written below, and clearing its kilobyte
    // for every packet showed in a profile of the moving camera's trace.
    Packet packet;
    if (count < Width) packet = Packet{};
    alignas(64) int valid[Width] = {};  // Embree reads the mask as one vector
    CameraRayContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    context.data = &data_;
    context.hits = hits;
    for (int i = 0; i < count; ++i) {
      hits[i].clear();
      packet.ray.org_x[i] = rays[i].origin.x;
      packet.ray.org_y[i] = rays[i].origin.y;
      packet.ray.org_z[i] = rays[i].origin.z;
      packet.ray.dir_x[i] = rays[i].direction.x;
      packet.ray.dir_y[i] = rays[i].direction.y;
      packet.ray.dir_z[i] = rays[i].direction.z;
      packet.ray.tnear[i] = rays[i].first;
      packet.ray.tfar[i] = cameraRays_.end(rays[i], limits[i]);
      packet.ray.time[i] = 0.0f;
      packet.ray.mask[i] = 0xFFFFFFFFu;
      packet.ray.id[i] = unsigned(i);
      packet.ray.flags[i] = 0u;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      valid[i] = embreeTakesRay(rays[i].origin, rays[i].direction) &&
                         packet.ray.tnear[i] <= packet.ray.tfar[i]
                     ? -1
                     : 0;
    }
    intersect(valid, scene_, &context, &packet);
    for (int i = 0; i < count; ++i) {
      std::vector<Hit>& found = hits[i];
      const bool opaque = packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
      const float nearest = packet.ray.tfar[i];
      if (opaque) dropFrom(found, nearest);
      inDepthOrder(found);
      if (!opaque) {
        depths[i] = limits[i];
        continue;
      }
      // Written in place, as in cameraFilter.
      Hit& hit = found.emplace_back();
      hit.t = nearest;
      hit.primitive = packet.hit.primID[i];
      hit.u = packet.hit.u[i];
      hit.v = packet.hit.v[i];
      depths[i] = opaqueDepth(rays[i], hit);
    }
  }

  // Every surface along origin + t direction, tnear < t < tfar, into `hits` in exact depth
  // order, ending at the first opaque one if there is one; true when there is.
  bool surfacesAlong(const glm::vec3& origin, const glm::vec3& direction, float tnear, float tfar,
                     std::vector<Hit>& hits) const {
    hits.clear();
    CameraRayContext context;
    rtcInitIntersectContext(&context);
    context.data = &data_;
    context.hits = &hits;
    RTCRayHit rayHit = singleRay(origin, direction, tnear, tfar);  // id 0: hits[0]
    if (embreeTakesRay(origin, direction) && tnear <= tfar)
      rtcIntersect1(scene_, &context, &rayHit);
    const bool opaque = rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    inDepthOrder(hits, opaque, Hit{rayHit.ray.tfar, rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v});
    return opaque;
  }

  // Whether hits[i] is a surface met before (a shared edge, a spatial split): composited once.
  // The hits are in depth order, so the ones at its distance are just before it: the search
  // stops at the first that is not (sameSurface widens with the distance only).
  bool metBefore(const Hit* hits, std::size_t i) const {
    const Triangle& tri = data_.triangles[hits[i].primitive];
    for (std::size_t j = i; j-- > 0;) {
      if (!sameSurface(hits[j].t, hits[i].t)) break;
      if (data_.triangles[hits[j].primitive].shape == tri.shape) return true;
    }
    return false;
  }

  // shading.frag's shade(), on the CPU, up to the shadows: appended to `row` (the shadowed
  // lights' light as terms waiting for their shadow rays) and returned. Shapes inside an
  // active group or a peeling separator are lit per pixel, as their shading program does;
  // elsewhere Coin's fixed-function GL lights each vertex and interpolates (Gouraud), and so
  // does this.
  const PendingShade& prepare(const Triangle& tri, const Hit& hit, const glm::vec3& position,
                              const glm::vec3& rayDirection, float lod, RayCounts& rays,
                              RowShading& row) const {
    // Made in place: the row keeps it (lighting() appends to the row's other vectors only).
    PendingShade& shade = row.shades.emplace_back();
    shade.image = imageOf(data_, tri);
    const SurfaceSample sample =
        sampleSurface(tri.colour, tri.texCoord, shade.image, hit.u, hit.v, lod);
    shade.rgb = glm::vec3(sample.colour);
    shade.alpha = sample.colour.a;
    shade.texel = sample.texel;
    if (tri.lit) lightSurface(tri, hit, position, rayDirection, sample, rays, row, shade);
    // The texture's models take opacity from the colour's and the texel's alphas alone.
    const float alpha =
        texturedColour(glm::vec4(0.0f, 0.0f, 0.0f, shade.alpha), shade.texel, shade.image).a;
    shade.opacity = isOpaque(alpha) ? 1.0f : glm::clamp(alpha, 0.0f, 1.0f);
    shade.material = tri.material;
    const Material& material = data_.materials[std::size_t(tri.material)];
    if (material.fogType != 0) shade.fog = fogWeight(material, position);
    shade.termsEnd = std::uint32_t(row.terms.size());
    return shade;
  }

  // prepare()'s lighting of a lit surface into shade.rgb. Apart, not inlined: the call of
  // prepare() with it, its registers saved and put back for every surface, was about a fifth
  // of a moving camera's shading through unlit glass.
  [[gnu::noinline]] void lightSurface(const Triangle& tri, const Hit& hit,
                                      const glm::vec3& position, const glm::vec3& rayDirection,
                                      const SurfaceSample& sample, RayCounts& rays, RowShading& row,
                                      PendingShade& shade) const {
    bool front = glm::dot(tri.geometricNormal, rayDirection) < 0.0f;
    if (tri.clockwise) front = !front;
    const float side = tri.twoSided && !front ? -1.0f : 1.0f;
    const float w = 1.0f - hit.u - hit.v;
    if (tri.perPixel) {
      const glm::vec3 normal = w * tri.normal[0] + hit.u * tri.normal[1] + hit.v * tri.normal[2];
      shade.rgb = lighting(tri, side * normal, position, glm::vec3(sample.colour), rays, row);
      shade.clampLit = true;
      return;
    }
    // Coin's fixed-function GL: each corner's light, clamped there (nothing casts outside
    // groups).
    const float weights[3] = {w, hit.u, hit.v};
    shade.rgb = glm::vec3(0.0f);
    for (std::size_t i = 0; i < 3; ++i) {
      const glm::vec3& corner = data_.positions[std::size_t(&tri - data_.triangles.data()) * 3 + i];
      shade.rgb += weights[i] * glm::clamp(lighting(tri, side * tri.normal[i], corner,
                                                    glm::vec3(tri.colour[i]), rays, row),
                                           0.0f, 1.0f);
    }
  }

  // The weight of a surface's own colour at `position` against its material's fog.
  [[gnu::noinline]] float fogWeight(const Material& material, const glm::vec3& position) const {
    SbVec3f eye;
    viewing_.multVecMatrix(SbVec3f(position.x, position.y, position.z), eye);
    const float z = std::fabs(eye[2]);
    const float fog =
        material.fogType == 1   ? (material.fogEnd - z) / (material.fogEnd - material.fogStart)
        : material.fogType == 2 ? std::exp(-material.fogDensity * z)
                                : std::exp(-material.fogDensity * material.fogDensity * z * z);
    return glm::clamp(fog, 0.0f, 1.0f);
  }

  // A surface's colour once its shadow rays (its terms from `termsBegin` on) are answered:
  // the shadowed lights' light added and clamped, the texture and the fog applied.
  glm::vec3 finish(const PendingShade& shade, const RowShading& row,
                   std::uint32_t termsBegin) const {
    glm::vec3 rgb = shade.rgb;
    if (shade.clampLit) {
      for (std::uint32_t k = termsBegin; k < shade.termsEnd; ++k)
        rgb += row.terms[k].light * row.answers[row.terms[k].query];
      rgb = glm::clamp(rgb, 0.0f, 1.0f);
    }
    glm::vec3 colour =
        glm::vec3(texturedColour(glm::vec4(rgb, shade.alpha), shade.texel, shade.image));
    const Material& material = data_.materials[std::size_t(shade.material)];
    if (material.fogType != 0) colour = glm::mix(material.fogColour, colour, shade.fog);
    return colour;
  }

  // Coin's lighting equation at one point, before GL clamps it: the casting lights' light on
  // a surface in a group waits in `row` for its shadow ray.
  glm::vec3 lighting(const Triangle& tri, glm::vec3 normal, const glm::vec3& position,
                     const glm::vec3& diffuse, RayCounts& rays, RowShading& row) const {
    const float length = glm::length(normal);
    normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 0.0f, 1.0f);
    const Material& material = data_.materials[std::size_t(tri.material)];
    glm::vec3 lit = material.emission + material.globalAmbient * material.ambient;
    const Group* group = tri.group >= 0 ? &data_.groups[std::size_t(tri.group)] : nullptr;
    // GL lights with the first kMaxGlLights lights in force (Coin drops the others).
    int inForce = 0;
    for (int index : data_.lightSets[std::size_t(tri.lightSet)]) {
      if (inForce++ >= kMaxGlLights) break;
      lit += contribution(data_.lights[std::size_t(index)], tri, group, normal, position, diffuse,
                          material, rays, row);
    }
    if (group != nullptr && group->bounce && options_.bounceSamples > 0)
      lit += diffuse * indirect(*group, tri, normal, position, rays);
    return lit;
  }

  // Where a light is seen from `position` (raytrace/LightEquation.h), in world space.
  static LightIncidence incidence(const Light& light, const glm::vec3& position) {
    LightPlacement placement;
    placement.position = light.type == LightType::Directional ? glm::vec4(light.towardsLight, 0.0f)
                                                              : glm::vec4(light.position, 1.0f);
    placement.falloff = light.attenuation;
    placement.spot = light.type == LightType::Spot;
    placement.spotDirection = light.spotDirection;
    placement.spotCosCutoff = light.spotCosCutoff;
    placement.spotExponent = light.spotExponent;
    return lightIncidence(placement, position);
  }

  // The colour model `group`'s casters shadow `light` in, or kNotCasting.
  int castingModel(const Group& group, const Light& light) const {
    return casting_[std::size_t(&group - data_.groups.data()) * data_.lights.size() +
                    std::size_t(&light - data_.lights.data())];
  }
  ShadowColourModel modelOf(const Group& group, const Light& light) const {
    return ShadowColourModel(castingModel(group, light));
  }

  // The transmittance of the group's casters between `position` (on a surface of geometric
  // normal `normal`) and the light.
  glm::vec3 castersTransmittance(const Group& group, const Light& light, const glm::vec3& position,
                                 const glm::vec3& normal, ShadowColourModel model) const {
    return light.type == LightType::Directional
               ? group.casters->transmittanceTowards(position, normal, light.towardsLight, model)
               : group.casters->transmittance(position, normal, light.position, model);
  }

  glm::vec3 contribution(const Light& light, const Triangle& tri, const Group* group,
                         const glm::vec3& normal, const glm::vec3& position,
                         const glm::vec3& diffuse, const Material& material, RayCounts& rays,
                         RowShading& row) const {
    const LightIncidence in = incidence(light, position);
    const glm::vec3 direct = directLight(
        normal, in.toLight, viewDirection_,
        Reflectance{diffuse, material.specular, material.shininess}, light.colour, light.colour);
    // Only light that reaches the surface asks for its shadow.
    if (direct == glm::vec3(0.0f)) return direct;
    if (group != nullptr && tri.shadowed && castingModel(*group, light) != kNotCasting) {
      ++rays.shadow;
      const bool directional = light.type == LightType::Directional;
      row.terms.push_back(ShadowTerm{in.attenuation * direct, std::uint32_t(row.queries.size())});
      row.queries.push_back(CasterScene::Query{position, tri.geometricNormal,
                                               directional ? light.towardsLight : light.position,
                                               modelOf(*group, light), directional});
      row.queryCasters.push_back(group->casters.get());
      return glm::vec3(0.0f);
    }
    return in.attenuation * direct;
  }

  // One diffuse bounce at `position` (shading normal `normal`, on `tri` in `group`): the mean,
  // over cosine-weighted directions about the normal, of the diffuse light that the group's
  // casting lights put directly on the first opaque surface of the group that way, times the
  // transmittance of the glass between. With Coin's Lambert (no 1 / pi: a light's colour is
  // its irradiance / pi), cosine-weighted sampling leaves the plain mean: L = kd(x) (1 / pi)
  // \int L(y) cos dw. Only the group's opaque, lit surfaces reflect; glass filters.
  glm::vec3 indirect(const Group& group, const Triangle& tri, const glm::vec3& normal,
                     const glm::vec3& position, RayCounts& rays) const {
    if (!group.casters || group.casting.empty()) return glm::vec3(0.0f);
    thread_local std::vector<Hit> hits;
    const int side = int(std::ceil(std::sqrt(double(options_.bounceSamples))));
    // One rotation of the strata per point (Cranley-Patterson), from the point's bits: the
    // picture is the same on every run and has no pattern shared by neighbouring pixels.
    std::uint32_t seed = 2166136261u;
    for (float c : {position.x, position.y, position.z}) {
      std::uint32_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      seed = (seed ^ bits) * 16777619u;
    }
    const auto unit = [&seed] {
      seed ^= seed << 13;
      seed ^= seed >> 17;
      seed ^= seed << 5;
      return float(seed >> 8) * (1.0f / 16777216.0f);
    };
    const float du = unit(), dv = unit();
    const glm::vec3 along = std::fabs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t1 = glm::normalize(glm::cross(normal, along));
    const glm::vec3 t2 = glm::cross(normal, t1);
    // The surface's own side: directions into it are counted as light that does not come.
    const glm::vec3 front =
        glm::dot(tri.geometricNormal, normal) >= 0.0f ? tri.geometricNormal : -tri.geometricNormal;
    const float scale =
        std::max({std::fabs(position.x), std::fabs(position.y), std::fabs(position.z), 1.0f});
    glm::vec3 sum(0.0f);
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const float u = std::fmod((float(i) + 0.5f) / float(side) + du, 1.0f);
        const float v = std::fmod((float(j) + 0.5f) / float(side) + dv, 1.0f);
        const float r = std::sqrt(u), phi = 6.28318531f * v;
        const glm::vec3 direction = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 +
                                    std::sqrt(std::max(0.0f, 1.0f - u)) * normal;
        if (!(glm::dot(direction, front) > 0.0f)) continue;
        ++rays.bounce;
        if (!surfacesAlong(position, direction, 1e-5f * scale,
                           std::numeric_limits<float>::infinity(), hits))
          continue;
        const Hit& hit = hits.back();
        const Triangle& reflector = data_.triangles[hit.primitive];
        if (reflector.group != tri.group || !reflector.lit) continue;
        const TextureImage* image = imageOf(data_, reflector);
        const SurfaceSample sample =
            sampleSurface(reflector.colour, reflector.texCoord, image, hit.u, hit.v);
        const glm::vec3 kd = glm::vec3(texturedColour(sample.colour, sample.texel, image));
        const glm::vec3 y = position + hit.t * direction;
        // The geometric normal is the corners' cross product, of any length.
        const glm::vec3 facing = glm::normalize(reflector.geometricNormal);
        const glm::vec3 ny = glm::dot(facing, direction) < 0.0f ? facing : -facing;
        for (int index : group.casting) {
          const Light& light = data_.lights[std::size_t(index)];
          const LightIncidence in = incidence(light, y);
          const float nDotL = glm::dot(ny, in.toLight);
          if (!(nDotL > 0.0f) || !(in.attenuation > 0.0f)) continue;
          const ShadowColourModel model = modelOf(group, light);
          glm::vec3 through(1.0f);
          for (std::size_t k = 0; k + 1 < hits.size(); ++k) {
            if (metBefore(hits.data(), k)) continue;
            const Triangle& glass = data_.triangles[hits[k].primitive];
            const TextureImage* glassImage = imageOf(data_, glass);
            const SurfaceSample g =
                sampleSurface(glass.colour, glass.texCoord, glassImage, hits[k].u, hits[k].v);
            through *= transmittance(
                glm::clamp(texturedColour(g.colour, g.texel, glassImage), 0.0f, 1.0f), model);
          }
          ++rays.shadow;
          sum += through * kd * light.colour * (nDotL * in.attenuation) *
                 castersTransmittance(group, light, y, reflector.geometricNormal, model);
        }
      }
    return sum / float(side * side);
  }

  const Extraction& data_;
  RTCScene scene_;
  int packetWidth_;  // camera rays traced together
  const TraceOptions& options_;
  SbMatrix viewing_;
  CameraRays cameraRays_;
  glm::vec3 viewDirection_{0.0f, 0.0f, 1.0f};
  static constexpr int kNotCasting = -1;
  std::vector<int> casting_;  // groups x lights: castingModel()
};

}  // namespace

// One worker's working memory: kept from trace to trace, as a frame's rows otherwise grew their
// vectors from nothing again, and on cache lines of its own, as neighbouring workers wrote
// into the same lines (the vectors' ends).
struct alignas(64) WorkerMemory {
  std::vector<Hit> hits[kMaxPacket];
  RowShading shading;
  RayCounts rays;
};

struct SceneTracer::Workers {
  std::vector<WorkerMemory> memory;
};

namespace {

// Row y's surfaces, shaded up to their shadows into the worker's row: those `keptRow` holds
// where `reuse`, else those its camera rays meet up to `limits` (GL's depth, or none), kept
// into `keptRow` when there is one.
void shadeSurfaces(const Tracer& tracer, int y, int width, const float* limits, bool reuse,
                   SurfacesMet::Row* keptRow, WorkerMemory& own) {
  if (keptRow != nullptr && !reuse) {
    keptRow->hits.clear();
    keptRow->ends.resize(std::size_t(width));
    keptRow->depth.resize(std::size_t(width));
  }
  RowShading& shades = own.shading;
  shades.clear();
  for (int x = 0; x < width; x += kMaxPacket) {
    const int count = std::min(kMaxPacket, width - x);
    CameraRay cameraRays[kMaxPacket];
    tracer.cameraRays().rays(x, y, count, cameraRays);
    if (reuse) {
      for (int i = 0; i < count; ++i) {
        const std::size_t at = std::size_t(x + i);
        const std::uint32_t begin = at > 0 ? keptRow->ends[at - 1] : 0u;
        tracer.gather(cameraRays[i], keptRow->hits.data() + begin, keptRow->ends[at] - begin,
                      keptRow->depth[at], own.rays, shades);
      }
      continue;
    }
    float ends[kMaxPacket];
    float depths[kMaxPacket];
    for (int i = 0; i < count; ++i) ends[i] = limits != nullptr ? limits[x + i] : 1.0f;
    std::vector<Hit>* found = own.hits;
    tracer.visible(cameraRays, ends, count, found, depths);
    for (int i = 0; i < count; ++i) {
      tracer.gather(cameraRays[i], found[i].data(), found[i].size(), depths[i], own.rays, shades);
      if (keptRow != nullptr) {
        const std::size_t at = std::size_t(x + i);
        keptRow->hits.insert(keptRow->hits.end(), found[i].begin(), found[i].end());
        keptRow->ends[at] = std::uint32_t(keptRow->hits.size());
        keptRow->depth[at] = depths[i];
      }
    }
  }
}

// The row's shadow rays answered: where the surfaces reused ask what `keptRow`'s answers
// answered, those answers (no ray traced, none counted); else traced, and kept.
void answerShadows(bool reuse, SurfacesMet::Row* keptRow, WorkerMemory& own) {
  RowShading& shades = own.shading;
  if (reuse && shades.asksAgain(keptRow->queries, keptRow->queryCasters)) {
    shades.answers = keptRow->answers;
    own.rays.shadow -= shades.queries.size();
    return;
  }
  shades.traceShadows();
  if (keptRow == nullptr) return;
  keptRow->queries = shades.queries;
  keptRow->queryCasters = shades.queryCasters;
  keptRow->answers = shades.answers;
}

// Row y's pixels composited into `out`.
void writeRow(const Tracer& tracer, const RowShading& shades, int y, TracedPixels& out) {
  const std::size_t row = std::size_t(y) * std::size_t(out.width);
  for (int x = 0; x < out.width; ++x) {
    const glm::vec4 p = tracer.resolve(shades, std::size_t(x));
    float* rgba = &out.rgba[(row + std::size_t(x)) * 4];
    rgba[0] = p.r;
    rgba[1] = p.g;
    rgba[2] = p.b;
    rgba[3] = p.a;
    out.depth[row + std::size_t(x)] = shades.depths[std::size_t(x)];
  }
}

}  // namespace

SceneTracer::SceneTracer(std::unique_ptr<Data> data)
    : data_(std::move(data)), workers_(std::make_unique<Workers>()) {}
SceneTracer::~SceneTracer() = default;

std::unique_ptr<SceneTracer> SceneTracer::fromScene(SoNode* root, int width, int height) {
  return std::unique_ptr<SceneTracer>(new SceneTracer(
      extract(width, height, [root](SoCallbackAction& action) { action.apply(root); })));
}

std::unique_ptr<SceneTracer> SceneTracer::fromPath(const SoPath* path, int width, int height) {
  return std::unique_ptr<SceneTracer>(
      new SceneTracer(extract(width, height, [path](SoCallbackAction& action) {
        action.apply(const_cast<SoPath*>(path));
      })));
}

bool SceneTracer::trace(const TraceOptions& options, TracedPixels& out) const {
  return trace(viewing(), projection(), nullptr, options, out);
}

bool SceneTracer::trace(const SbMatrix& viewing, const SbMatrix& projection,
                        const float* depthLimit, const TraceOptions& options,
                        TracedPixels& out) const {
  const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
  out.width = options.width;
  out.height = options.height;
  // Every pixel is written below (a cancelled trace is not used).
  out.rgba.resize(pixels * 4);
  out.depth.resize(pixels);
  out.cameraRays = 0;
  out.shadowRays = 0;
  out.bounceRays = 0;
  const Tracer tracer(data_->extraction, data_->scene.get(), data_->packetWidth, viewing,
                      projection, options);
  const int workers = workerCount(options.threads);
  std::vector<WorkerMemory>& memory = workers_->memory;
  if (memory.size() < std::size_t(workers)) memory.resize(std::size_t(workers));
  for (WorkerMemory& worker : memory) worker.rays = RayCounts{};
  SurfacesMet* kept = options.surfaces;
  const bool reuse = kept != nullptr && options.reuseSurfaces && options.height > 0 &&
                     kept->rows.size() == std::size_t(options.height) &&
                     kept->rows.front().ends.size() == std::size_t(options.width);
  if (kept != nullptr && !reuse) kept->rows.resize(std::size_t(options.height));
  parallelRows(
      options.height, workers,
      [&](int y, int worker) {
        // GL's rows run bottom to top.
        const float* limits =
            depthLimit != nullptr
                ? depthLimit + std::size_t(options.height - 1 - y) * std::size_t(options.width)
                : nullptr;
        WorkerMemory& own = memory[std::size_t(worker)];
        SurfacesMet::Row* keptRow = kept != nullptr ? &kept->rows[std::size_t(y)] : nullptr;
        shadeSurfaces(tracer, y, options.width, limits, reuse, keptRow, own);
        answerShadows(reuse, keptRow, own);
        writeRow(tracer, own.shading, y, out);
        if (options.rowsDone) ++*options.rowsDone;
      },
      options.cancel);
  // A cancelled trace leaves rows it did not reach: nothing kept may be reused.
  if (options.cancel && options.cancel->load()) {
    if (kept != nullptr) kept->rows.clear();
    return false;
  }
  if (!reuse) out.cameraRays = pixels;
  for (const WorkerMemory& worker : memory) {
    out.shadowRays += worker.rays.shadow;
    out.bounceRays += worker.rays.bounce;
  }
  return true;
}

}  // namespace ivshadow
