#include "headless/EglHeadlessContext.h"

#include <Inventor/SoDB.h>
#include <Inventor/errors/SoDebugError.h>
#include <epoxy/egl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace ivshadow {
namespace {

std::string eglErrorName(EGLint code) {
  switch (code) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    default:
      return "EGL error " + std::to_string(code);
  }
}

std::string failure(const std::string& call) {
  return call + " failed (" + eglErrorName(eglGetError()) + ")";
}

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* at = std::strstr(list, name); at != nullptr; at = std::strstr(at + 1, name)) {
    const bool startOk = at == list || at[-1] == ' ';
    const bool endOk = at[length] == ' ' || at[length] == '\0';
    if (startOk && endOk) return true;
  }
  return false;
}

struct Candidate {
  std::string platform;
  EGLDisplay display;
};

// A hardware device as --stats names it: its DRM node where the driver tells it
// (EGL_EXT_device_drm) and its CUDA ordinal on NVIDIA (EGL_NV_device_cuda), so that a report
// from a machine with several GPUs says which one drew.
std::string deviceName(EGLDeviceEXT device, const char* extensions) {
  std::string name = "device";
  if (hasExtension(extensions, "EGL_EXT_device_drm")) {
    const char* file = eglQueryDeviceStringEXT(device, EGL_DRM_DEVICE_FILE_EXT);
    if (file != nullptr && *file != '\0') name += std::string(" ") + file;
  }
  EGLAttrib ordinal = -1;
  if (hasExtension(extensions, "EGL_NV_device_cuda") &&
      eglQueryDeviceAttribEXT(device, EGL_CUDA_DEVICE_NV, &ordinal))
    name += " (CUDA device " + std::to_string(ordinal) + ")";
  return name;
}

// EGL devices, hardware ones first; Mesa marks its CPU device with EGL_MESA_device_software.
std::vector<Candidate> deviceDisplays(bool software) {
  std::vector<Candidate> out;
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return out;
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  eglQueryDevicesEXT(count, devices.data(), &count);
  for (EGLint i = 0; i < count; ++i) {
    const char* extensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
    if (hasExtension(extensions, "EGL_MESA_device_software") != software) continue;
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    if (display != EGL_NO_DISPLAY)
      out.push_back({software ? "software device" : deviceName(devices[i], extensions), display});
  }
  return out;
}

std::vector<Candidate> candidateDisplays(std::string& error) {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const bool devices = hasExtension(clientExtensions, "EGL_EXT_platform_device") &&
                       hasExtension(clientExtensions, "EGL_EXT_device_enumeration");
  const bool surfaceless = hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless");
  const char* forced = std::getenv("IVSHADOW_EGL_PLATFORM");
  const std::string want = forced ? forced : "";

  std::vector<Candidate> out;
  if ((want.empty() || want == "device") && devices) {
    for (auto& c : deviceDisplays(false)) out.push_back(c);
  }
  if ((want.empty() || want == "surfaceless") && surfaceless) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY) out.push_back({"surfaceless", display});
  }
  if ((want.empty() || want == "device") && devices) {
    for (auto& c : deviceDisplays(true)) out.push_back(c);
  }
  if (want.empty() || want == "default") {
    EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display != EGL_NO_DISPLAY) out.push_back({"default", display});
  }
  if (out.empty()) {
    error = want.empty() ? "no EGL display: eglGetPlatformDisplayEXT/eglGetDisplay returned "
                           "EGL_NO_DISPLAY for every platform (is libegl-mesa0 installed?)"
                         : "IVSHADOW_EGL_PLATFORM=" + want + " is not available here";
  }
  return out;
}

// Creates a 4.5 compatibility context, falling back to any compatibility context so that
// older drivers still get plain rendering.
EGLContext createContext(EGLDisplay display, std::string& error) {
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(extensions, "EGL_KHR_no_config_context") &&
      !hasExtension(extensions, "EGL_MESA_configless_context")) {
    const EGLint attributes[] = {EGL_SURFACE_TYPE,
                                 EGL_PBUFFER_BIT,
                                 EGL_RENDERABLE_TYPE,
                                 EGL_OPENGL_BIT,
                                 EGL_RED_SIZE,
                                 8,
                                 EGL_DEPTH_SIZE,
                                 24,
                                 EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, attributes, &config, 1, &count) || count < 1) {
      error = failure("eglChooseConfig (desktop OpenGL, 8-bit colour, 24-bit depth)");
      return EGL_NO_CONTEXT;
    }
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    error = failure("eglBindAPI(EGL_OPENGL_API)");
    return EGL_NO_CONTEXT;
  }
  const EGLint version45[] = {EGL_CONTEXT_MAJOR_VERSION,
                              4,
                              EGL_CONTEXT_MINOR_VERSION,
                              5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                              EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, version45);
  if (context == EGL_NO_CONTEXT) {
    const EGLint anyVersion[] = {EGL_NONE};
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, anyVersion);
  }
  if (context == EGL_NO_CONTEXT) error = failure("eglCreateContext (OpenGL 4.5 compatibility)");
  return context;
}

}  // namespace

std::unique_ptr<EglHeadlessContext> EglHeadlessContext::create(std::string& error) {
  std::vector<Candidate> candidates = candidateDisplays(error);
  std::string reasons;
  for (const Candidate& candidate : candidates) {
    EGLint major = 0, minor = 0;
    std::string why;
    if (!eglInitialize(candidate.display, &major, &minor)) {
      why = failure("eglInitialize");
    } else if (EGLContext context = createContext(candidate.display, why);
               context != EGL_NO_CONTEXT) {
      if (eglMakeCurrent(candidate.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        std::unique_ptr<EglHeadlessContext> result(new EglHeadlessContext);
        result->display_ = candidate.display;
        result->context_ = context;
        result->platform_ = candidate.platform;
        // A GPU that is there but cannot make a context must not pass unnoticed: the
        // rendering goes on, on the software platform that could.
        if (!reasons.empty() && candidates.front().platform.rfind("device", 0) == 0) {
          const std::string warning = "the GPU's EGL device could not be used (" + reasons +
                                      "); rendering on the " + candidate.platform + " platform";
          if (SoDB::isInitialized())
            SoDebugError::postWarning("ivshadow", "%s", warning.c_str());
          else
            std::fprintf(stderr, "ivshadow: warning: %s\n", warning.c_str());
        }
        return result;
      }
      why = failure("eglMakeCurrent without a surface");
      eglDestroyContext(candidate.display, context);
    }
    reasons += (reasons.empty() ? "" : "; ") + candidate.platform + " platform: " + why;
  }
  if (!candidates.empty()) error = "could not create a GL context with EGL: " + reasons;
  return nullptr;
}

EglHeadlessContext::~EglHeadlessContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
}

bool EglHeadlessContext::isCurrent() const {
  return context_ != nullptr && eglGetCurrentContext() == context_;
}

bool EglHeadlessContext::makeCurrent() {
  return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE;
}

}  // namespace ivshadow
