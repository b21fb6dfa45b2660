#include "raytrace/CameraFilter.h"

#include "raytrace/SurfaceOptics.h"

namespace ivshadow {
namespace detail {
namespace {

float opacity(const Extraction& data, const Triangle& tri, float u, float v) {
  const TextureImage* image = imageOf(data, tri);
  const SurfaceSample sample = sampleSurface(tri.colour, tri.texCoord, image, u, v);
  return texturedColour(sample.colour, sample.texel, image).a;
}

}  // namespace

void cameraFilter(const RTCFilterFunctionNArguments* args) {
  auto& context = *static_cast<CameraRayContext*>(args->context);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    SurfacesMet::Hit hit;
    hit.primitive = RTCHitN_primID(args->hit, args->N, i);
    hit.u = RTCHitN_u(args->hit, args->N, i);
    hit.v = RTCHitN_v(args->hit, args->N, i);
    hit.t = RTCRayN_tfar(args->ray, args->N, i);
    const float alpha =
        opacity(*context.data, context.data->triangles[hit.primitive], hit.u, hit.v);
    // An opaque surface is accepted: Embree then only looks for nearer ones. The others are
    // collected and passed over.
    if (isOpaque(alpha)) continue;
    if (alpha > 0.0f) context.hits[RTCRayN_id(args->ray, args->N, i)].push_back(hit);
    args->valid[i] = 0;
  }
}

}  // namespace detail
}  // namespace ivshadow
