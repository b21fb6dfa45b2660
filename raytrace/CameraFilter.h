#pragma once

#include "raytrace/SceneExtraction.h"
#include "raytrace/SceneTracer.h"

#include <embree3/rtcore.h>

#include <vector>

namespace ivshadow {
namespace detail {

// Every surface a camera ray meets, collected by cameraFilter: hits[id] for the ray whose id
// is `id` (a single ray's is 0).
struct CameraRayContext : RTCIntersectContext {
  const Extraction* data = nullptr;
  std::vector<SurfacesMet::Hit>* hits = nullptr;
};

// Embree's filter function of the camera rays' scene (built by SceneTracer::extract): it
// accepts an opaque surface, so Embree looks only for nearer ones, and collects every other
// surface a camera ray meets into its CameraRayContext, passing over it.
void cameraFilter(const RTCFilterFunctionNArguments* args);

}  // namespace detail
}  // namespace ivshadow
