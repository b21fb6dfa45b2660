#include "raytrace/EmbreeHandles.h"

namespace ivshadow {
namespace {

bool monitor(void* user, ssize_t bytes, bool post) {
  auto& memory = *static_cast<EmbreeMemory*>(user);
  const std::int64_t after = memory.bytes.fetch_add(bytes) + bytes;
  // Only a call before the allocation (post false) can refuse it; a refused allocation is
  // never made, so it is not counted.
  if (!post && bytes > 0 && memory.limit > 0 && after > memory.limit) {
    memory.bytes.fetch_sub(bytes);
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

int nativePacketWidth(RTCDevice device) {
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) return 8;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) return 4;
  return 1;
}

EmbreeScene buildTriangleScene(RTCDevice device, std::size_t count,
                               const std::function<const float*(std::size_t)>& corner,
                               RTCFilterFunctionN filter, std::string& error) {
  EmbreeScene scene(rtcNewScene(device));
  if (!scene) {
    error = "Embree could not create a scene";
    return EmbreeScene();
  }
  // Robust: no ray slips through the shared edge of two triangles.
  rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);
  if (count > 0) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* positions = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), count * 3));
    auto* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), count));
    if (positions == nullptr || indices == nullptr) {
      rtcReleaseGeometry(geometry);
      error = "Embree could not allocate " + std::to_string(count) + " triangles";
      return EmbreeScene();
    }
    for (std::size_t i = 0; i < count * 3; ++i) {
      const float* p = corner(i);
      for (std::size_t k = 0; k < 3; ++k) positions[i * 3 + k] = p[k];
      indices[i] = static_cast<unsigned int>(i);
    }
    // Moved triangles (a transform changed) refit the tree instead of rebuilding it.
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_REFIT);
    rtcSetGeometryIntersectFilterFunction(geometry, filter);
    rtcSetGeometryOccludedFilterFunction(geometry, filter);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene.get(), geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene.get());
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE) {
    error = "Embree could not build the bounding volume hierarchy of " + std::to_string(count) +
            " triangles (out of memory?)";
    return EmbreeScene();
  }
  return scene;
}

}  // namespace ivshadow
