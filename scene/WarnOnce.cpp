#include "scene/WarnOnce.h"

#include <mutex>
#include <set>
#include <utility>

namespace ivshadow {

namespace {

// Never destroyed: a node destroyed during static destruction may still warn.
std::mutex& warnedMutex() {
  static auto* mutex = new std::mutex;
  return *mutex;
}
std::set<std::pair<const void*, std::string>>& warned() {
  static auto* set = new std::set<std::pair<const void*, std::string>>;
  return *set;
}

}  // namespace

bool firstWarning(const void* subject, const std::string& what) {
  const std::lock_guard<std::mutex> lock(warnedMutex());
  return warned().emplace(subject, what).second;
}

void forgetWarnings(const void* subject) {
  const std::lock_guard<std::mutex> lock(warnedMutex());
  auto& set = warned();
  set.erase(set.lower_bound({subject, std::string()}),
            set.lower_bound({static_cast<const char*>(subject) + 1, std::string()}));
}

void forgetAllWarnings() {
  const std::lock_guard<std::mutex> lock(warnedMutex());
  warned().clear();
}

}  // namespace ivshadow
