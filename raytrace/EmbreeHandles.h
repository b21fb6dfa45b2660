#pragma once

#include <embree3/rtcore.h>

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

// A device using every core; null with Embree's reason in `error` when it cannot be made.
EmbreeDevice createEmbreeDevice(std::string& error);

}  // namespace ivshadow
