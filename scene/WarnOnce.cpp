#include "scene/WarnOnce.h"

#include <mutex>
#include <set>
#include <utility>

namespace ivshadow {

bool firstWarning(const void* subject, const std::string& what) {
  // Never destroyed: a node destroyed during static destruction may still warn.
  static std::mutex* mutex = new std::mutex;
  static auto* warned = new std::set<std::pair<const void*, std::string>>;
  const std::lock_guard<std::mutex> lock(*mutex);
  return warned->emplace(subject, what).second;
}

}  // namespace ivshadow
