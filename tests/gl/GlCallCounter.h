#pragma once

namespace ivshadow::test {

// Counts the GL state queries and uniform look-ups made through libepoxy (as the plugin makes
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
  void reset();
};

}  // namespace ivshadow::test
