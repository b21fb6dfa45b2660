#pragma once

#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/misc/SoContextHandler.h>

#include <cstdint>
#include <map>
#include <memory>

namespace ivshadow {

// GL resources of one node, one `T` per GL context (Coin's cache context ids). A context's
// `T` dies with the context (SoContextHandler calls back while it is current); those still
// alive when the owner dies are handed to SoGLCacheContextElement::scheduleDeleteCallback,
// which deletes them the next time their context is current.
template <typename T>
class PerContext {
 public:
  PerContext() { SoContextHandler::addContextDestructionCallback(destroyed, this); }
  ~PerContext() {
    SoContextHandler::removeContextDestructionCallback(destroyed, this);
    for (auto& [id, resources] : byContext_) {
      if (!resources) continue;
      SoGLCacheContextElement::scheduleDeleteCallback(
          id, [](void* doomed, std::uint32_t) { delete static_cast<T*>(doomed); },
          resources.release());
    }
  }
  PerContext(const PerContext&) = delete;
  PerContext& operator=(const PerContext&) = delete;

  // The context's resources, made by `make()` (which may return null) on first use.
  template <typename Make>
  T* get(std::uint32_t context, Make make) {
    auto found = byContext_.find(context);
    if (found == byContext_.end()) found = byContext_.emplace(context, make()).first;
    return found->second.get();
  }

 private:
  static void destroyed(std::uint32_t context, void* self) {
    static_cast<PerContext*>(self)->byContext_.erase(context);
  }
  std::map<std::uint32_t, std::unique_ptr<T>> byContext_;
};

}  // namespace ivshadow
