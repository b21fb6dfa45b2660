#include "gl/GlMemoryBudget.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace ivshadow {
namespace {

// GL_NVX_gpu_memory_info and GL_ATI_meminfo report kilobytes.
constexpr GLenum kNvxCurrentAvailable = 0x9049;  // GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
constexpr GLenum kAtiTextureFree = 0x87FC;       // TEXTURE_FREE_MEMORY_ATI

std::uint64_t memAvailable() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024u;
  return 0;
}

}  // namespace

std::uint64_t glMemoryBudget(bool softwareRenderer) {
  std::uint64_t budget = 0;
  if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
    GLint kilobytes = 0;
    glGetIntegerv(kNvxCurrentAvailable, &kilobytes);
    budget = std::uint64_t(std::max(kilobytes, 0)) * 1024u;
  } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
    GLint free[4] = {0, 0, 0, 0};
    glGetIntegerv(kAtiTextureFree, free);
    budget = std::uint64_t(std::max(free[0], 0)) * 1024u;
  } else if (softwareRenderer) {
    budget = memAvailable();
  }
  return budget;
}

}  // namespace ivshadow
