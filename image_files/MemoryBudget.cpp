#include "image_files/MemoryBudget.h"

#include "scene/InputError.h"

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace ivshadow {
namespace {

std::string gibibytes(double bytes) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << bytes / double(1ull << 30) << " GiB";
  return out.str();
}

}  // namespace

std::uint64_t MemoryBudget::available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024u;
  const long pages = ::sysconf(_SC_AVPHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0u;
}

std::uint64_t MemoryBudget::estimate(const ImageSize& size, const MemoryCost& cost, int copies) {
  const double pixels = double(size.width) * double(size.height);
  return std::uint64_t(std::ceil(double(copies) * (cost.fixedBytes + cost.bytesPerPixel * pixels)));
}

void MemoryBudget::check(const ImageSize& size, const MemoryCost& cost, const std::string& what,
                         int copies, std::uint64_t availableBytes) {
  const std::uint64_t needed = estimate(size, cost, copies);
  if (needed <= availableBytes) return;
  std::ostringstream message;
  message << "--size " << size.toString() << ": error: " << what << " at this size needs about "
          << gibibytes(double(needed)) << " of memory ("
          << (copies > 1 ? std::to_string(copies) + " at once, " : std::string()) << "about "
          << std::lround(cost.bytesPerPixel) << " bytes per pixel), but only "
          << gibibytes(double(availableBytes))
          << " is available (MemAvailable); choose a smaller size";
  throw InputError(message.str());
}

}  // namespace ivshadow
