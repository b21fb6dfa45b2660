#pragma once

#include "image_files/ImageSize.h"

#include <cstdint>
#include <string>

namespace ivshadow {

// Peak memory of a command as `fixedBytes` plus `bytesPerPixel` for each pixel of the image,
// measured (maximum resident set, /usr/bin/time -v) at two sizes; README "Image sizes" lists
// the figures and how they were taken.
struct MemoryCost {
  double bytesPerPixel;
  double fixedBytes;
};

// Refuses, before any work, image sizes whose buffers would not fit in memory: a render that
// would run out is killed by the kernel minutes later with no word.
class MemoryBudget {
 public:
  // What the machine can give without swapping: MemAvailable of /proc/meminfo, or free
  // physical pages where there is none.
  static std::uint64_t available();

  // Throws InputError naming --size, `what` ("a render with traced (RAYS) shadows"), the
  // estimate, the per-pixel figure and what is available when `copies` runs of `cost` at
  // `size` need more than `availableBytes`.
  static void check(const ImageSize& size, const MemoryCost& cost, const std::string& what,
                    int copies, std::uint64_t availableBytes);
  static std::uint64_t estimate(const ImageSize& size, const MemoryCost& cost, int copies);
};

}  // namespace ivshadow
