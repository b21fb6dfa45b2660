#include "raytrace/EmbreeHandles.h"

namespace ivshadow {

EmbreeDevice createEmbreeDevice(std::string& error) {
  RTCDevice device = rtcNewDevice(nullptr);
  if (device == nullptr) {
    const RTCError code = rtcGetDeviceError(nullptr);
    error = "Embree could not create a device (error " + std::to_string(int(code)) + ")";
    return EmbreeDevice();
  }
  return EmbreeDevice(device);
}

}  // namespace ivshadow
