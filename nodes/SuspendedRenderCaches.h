#pragma once

namespace ivshadow {

// While one exists, no SoSeparator of the process records or replays a render cache: passes
// that draw a subgraph several times with state and uniforms of their own (the RAYS capture,
// the peel and fragment-list passes) must not record them into a cache replayed later, nor
// replay one recorded under other state between their passes. SoSeparator's number of render
// caches is one for the process: the first suspension to begin saves it, the last to end
// restores it, so that several contexts rendering at once on threads leave it as they found
// it (another context's frame meanwhile draws slower, never wrongly).
class SuspendedRenderCaches {
 public:
  SuspendedRenderCaches();
  ~SuspendedRenderCaches();
  SuspendedRenderCaches(const SuspendedRenderCaches&) = delete;
  SuspendedRenderCaches& operator=(const SuspendedRenderCaches&) = delete;
};

}  // namespace ivshadow
