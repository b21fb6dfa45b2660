#include "nodes/SuspendedRenderCaches.h"

#include <Inventor/nodes/SoSeparator.h>

#include <mutex>

namespace ivshadow {
namespace {

struct Suspensions {
  std::mutex mutex;
  int active = 0;
  int saved = 0;
};

Suspensions& suspensions() {
  static Suspensions state;
  return state;
}

}  // namespace

SuspendedRenderCaches::SuspendedRenderCaches() {
  Suspensions& state = suspensions();
  const std::lock_guard<std::mutex> lock(state.mutex);
  if (state.active++ == 0) {
    state.saved = SoSeparator::getNumRenderCaches();
    SoSeparator::setNumRenderCaches(0);
  }
}

SuspendedRenderCaches::~SuspendedRenderCaches() {
  Suspensions& state = suspensions();
  const std::lock_guard<std::mutex> lock(state.mutex);
  if (--state.active == 0) SoSeparator::setNumRenderCaches(state.saved);
}

}  // namespace ivshadow
