#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
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

// A device using every core; null with Embree's reason in `error` when it cannot be made.
// `memory`, when given, must outlive the device.
EmbreeDevice createEmbreeDevice(std::string& error, EmbreeMemory* memory = nullptr);

}  // namespace ivshadow
