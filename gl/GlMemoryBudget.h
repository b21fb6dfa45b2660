#pragma once

#include <cstdint>

namespace ivshadow {

// The memory a GL allocation in the current context may take, as far as it can be known:
// the free video memory a driver reports (GL_NVX_gpu_memory_info, GL_ATI_meminfo); on a
// software rasteriser, which allocates in system memory, MemAvailable of /proc/meminfo; 0 when
// none of these says (then only GL_OUT_OF_MEMORY tells).
std::uint64_t glMemoryBudget(bool softwareRenderer);

}  // namespace ivshadow
