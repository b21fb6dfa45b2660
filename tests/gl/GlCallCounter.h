#pragma once

#include <string>
#include <vector>

namespace ivshadow::test {

// Counts the GL state queries, uniform look-ups, glDrawArrays and glBlitNamedFramebuffer calls
// made through libepoxy (as the plugin makes
// them; Coin's own calls go through its own loader) while it lives. Epoxy dispatches through
// writable function pointers: each is resolved first, then swapped for a counting wrapper, and
// put back on destruction. One counter at a time, on the thread with the current context.
class GlCallCounter {
 public:
  GlCallCounter();
  ~GlCallCounter();
  GlCallCounter(const GlCallCounter&) = delete;
  GlCallCounter& operator=(const GlCallCounter&) = delete;

  // glGetIntegerv, glGetIntegeri_v, glGetBooleanv, glGetFloatv and glIsEnabled calls.
  long queries() const;
  // glGetUniformLocation calls.
  long uniformLookups() const;
  // Reads of a query's result (glGetQueryObjectuiv and glGetQueryObjectui64v with
  // GL_QUERY_RESULT) that GL did not have yet: each stalls the CPU until the GPU gets there.
  long resultWaits() const;
  // The names of the debug groups pushed (glPushDebugGroup), in order.
  const std::vector<std::string>& debugGroups() const;
  // glDrawArrays calls (every pass of the plugin that draws a screen triangle).
  long draws() const;
  // glBlitNamedFramebuffer calls.
  long blits() const;
  void reset();
};

}  // namespace ivshadow::test
