#include "raytrace/CameraFilter.h"

#include "raytrace/SurfaceOptics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ivshadow {
namespace detail {
namespace {

// What `tri` covers at (u, v): its coverage, or where that is Sampled, its alpha's there.
Coverage coverageAt(const Extraction& data, const Triangle& tri, float u, float v) {
  if (tri.coverage != Coverage::Sampled) return tri.coverage;
  const TextureImage* image = imageOf(data, tri);
  const SurfaceSample sample = sampleSurface(tri.colour, tri.texCoord, image, u, v);
  const float alpha = texturedColour(sample.colour, sample.texel, image).a;
  return isOpaque(alpha) ? Coverage::Opaque
         : alpha > 0.0f  ? Coverage::Transparent
                         : Coverage::Clear;
}

}  // namespace

Coverage coverageOf(const float alphas[3], bool textured) {
  if (textured) return Coverage::Sampled;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(alphas[i])) return Coverage::Sampled;
  const float lowest = std::min({alphas[0], alphas[1], alphas[2]});
  const float highest = std::max({alphas[0], alphas[1], alphas[2]});
  constexpr float kMargin = 1e-4f;
  if (lowest == 0.0f && highest == 0.0f) return Coverage::Clear;
  if (lowest > kMargin && highest < kOpaqueAlpha - kMargin) return Coverage::Transparent;
  if (lowest > kOpaqueAlpha + kMargin && highest < 2.0f) return Coverage::Opaque;
  return Coverage::Sampled;
}

void cameraFilter(const RTCFilterFunctionNArguments* args) {
  auto& context = *static_cast<CameraRayContext*>(args->context);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const std::uint32_t primitive = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    const Coverage coverage = coverageAt(*context.data, context.data->triangles[primitive], u, v);
    // An opaque surface is accepted: Embree then only looks for nearer ones. The others are
    // collected and passed over. The hit is written in place, field by field: a Hit put
    // together on the stack and copied in as one vector waited for its parts' stores, half
    // of this filter's time.
    if (coverage == Coverage::Opaque) continue;
    if (coverage == Coverage::Transparent) {
      SurfacesMet::Hit& hit = context.hits[RTCRayN_id(args->ray, args->N, i)].emplace_back();
      hit.t = RTCRayN_tfar(args->ray, args->N, i);
      hit.primitive = primitive;
      hit.u = u;
      hit.v = v;
    }
    args->valid[i] = 0;
  }
}

}  // namespace detail
}  // namespace ivshadow
