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

// The coverage of a triangle of corner alphas `alphas` (textured: Sampled), as cameraFilter
// takes it. A point's alpha is w a0 + u a1 + v a2 in floats, with Embree's barycentrics within
// a few units of rounding of [0, 1]: it stays within a relative 1e-6 of the corners' range, so
// a range clear of the thresholds by 1e-4 decides every point as its interpolated alpha would.
// Corners all exactly 0 interpolate to 0.
Coverage coverageOf(const float alphas[3], bool textured);

}  // namespace detail
}  // namespace ivshadow
