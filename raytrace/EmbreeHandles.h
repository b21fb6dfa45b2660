#pragma once

#include "ivshadow/Export.h"

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace ivshadow {

struct EmbreeDeviceRelease {
  void operator()(RTCDeviceTy* device) const { rtcReleaseDevice(device); }
};
struct EmbreeSceneRelease {
  void operator()(RTCSceneTy* scene) const { rtcReleaseScene(scene); }
};

// Move-only owners of Embree objects.
using EmbreeDevice = std::unique_ptr<RTCDeviceTy, EmbreeDeviceRelease>;
using EmbreeScene = std::unique_ptr<RTCSceneTy, EmbreeSceneRelease>;

// What a device holds, kept up to date by Embree's memory monitor, and how much it may hold:
// an allocation past `limit` (0: no limit) fails, and Embree reports RTC_ERROR_OUT_OF_MEMORY
// instead of the process running out.
struct EmbreeMemory {
  std::atomic<std::int64_t> bytes{0};
  std::int64_t limit = 0;
};

// A robust scene of `count` separate triangles whose corner i (0 .. 3 count - 1) is at
// corner(i)[0..2], with `filter` called for every hit found by rtcIntersect or rtcOccluded
// (triangle k is primitive k; in a packet, the filter finds its ray by the ray's id). Null with the
// reason in `error` when Embree cannot hold it.
IVSHADOW_INTERNAL EmbreeScene buildTriangleScene(
    RTCDevice device, std::size_t count, const std::function<const float*(std::size_t)>& corner,
    RTCFilterFunctionN filter, std::string& error);

// The widest ray packet `device` traces natively (16, 8 or 4 rays), or 1 when it traces none:
// a packet of that width walks the tree once for all its rays.
IVSHADOW_INTERNAL int nativePacketWidth(RTCDevice device);

// One ray for rtcIntersect1 (id 0) from `origin` along `direction` over [tnear, tfar], meeting
// every geometry, with no hit yet.
inline RTCRayHit singleRay(const glm::vec3& origin, const glm::vec3& direction, float tnear,
                           float tfar) {
  RTCRayHit rayHit{};
  rayHit.ray.org_x = origin.x;
  rayHit.ray.org_y = origin.y;
  rayHit.ray.org_z = origin.z;
  rayHit.ray.dir_x = direction.x;
  rayHit.ray.dir_y = direction.y;
  rayHit.ray.dir_z = direction.z;
  rayHit.ray.tnear = tnear;
  rayHit.ray.tfar = tfar;
  rayHit.ray.mask = 0xFFFFFFFFu;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return rayHit;
}

// A device using every core; null with Embree's reason in `error` when it cannot be made.
// `memory`, when given, must outlive the device.
IVSHADOW_INTERNAL EmbreeDevice createEmbreeDevice(std::string& error,
                                                  EmbreeMemory* memory = nullptr);

}  // namespace ivshadow
