#pragma once

#include <memory>
#include <string>

namespace ivshadow {

// A GL 4.5 compatibility-profile context without any window, made with EGL. The platform is
// picked in this order: a hardware EGL device (EGL_EXT_platform_device, e.g. NVIDIA), Mesa's
// surfaceless platform, a software EGL device, the default display. IVSHADOW_EGL_PLATFORM=
// device|surfaceless|default forces one. The context is current on the creating thread.
class EglHeadlessContext {
 public:
  // Returns null and says which EGL call failed in `error` when no context can be made.
  static std::unique_ptr<EglHeadlessContext> create(std::string& error);
  ~EglHeadlessContext();

  EglHeadlessContext(const EglHeadlessContext&) = delete;
  EglHeadlessContext& operator=(const EglHeadlessContext&) = delete;

  bool makeCurrent();
  // Whether this context is current on the calling thread.
  bool isCurrent() const;
  // Which EGL platform the context lives on, e.g. "surfaceless", "software device" or, for a
  // GPU, "device" followed by its DRM node and CUDA ordinal where the driver names them.
  const std::string& platform() const { return platform_; }

 private:
  EglHeadlessContext() = default;

  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string platform_;
};

}  // namespace ivshadow
