#include "raytrace/EmbreeHandles.h"

namespace ivshadow {
namespace {

bool monitor(void* user, ssize_t bytes, bool) {
  auto& memory = *static_cast<EmbreeMemory*>(user);
  const std::int64_t after = memory.bytes.fetch_add(bytes) + bytes;
  if (bytes > 0 && memory.limit > 0 && after > memory.limit) {
    memory.bytes.fetch_sub(bytes);  // a refused allocation is not made
    return false;
  }
  return true;
}

}  // namespace

EmbreeDevice createEmbreeDevice(std::string& error, EmbreeMemory* memory) {
  RTCDevice device = rtcNewDevice(nullptr);
  if (device == nullptr) {
    const RTCError code = rtcGetDeviceError(nullptr);
    error = "Embree could not create a device (error " + std::to_string(int(code)) + ")";
    return EmbreeDevice();
  }
  if (memory != nullptr) rtcSetDeviceMemoryMonitorFunction(device, monitor, memory);
  return EmbreeDevice(device);
}

}  // namespace ivshadow
