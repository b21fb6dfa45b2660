#pragma once

#include <mutex>
#include <string>
#include <vector>

namespace ivshadow::test {

// The GL errors of one context: what KHR_debug reports as each failing call is made (output
// is synchronous, so the report comes while the call is on the stack) and what glGetError has
// kept. Made with the context current; the context must stop using it (stop(), or the context
// destroyed) before it is destroyed, since GL holds its address.
class GlDebugErrors {
 public:
  // Starts collecting on the current context. What the context held before (context creation
  // is not the test's doing) is dropped.
  GlDebugErrors();
  GlDebugErrors(const GlDebugErrors&) = delete;
  GlDebugErrors& operator=(const GlDebugErrors&) = delete;

  // Whether the context reports errors through KHR_debug; without it only glGetError is read.
  bool debugOutput() const { return debugOutput_; }
  // The errors since the last call, one line each ("" when none), and forgets them. With
  // `contextCurrent` (the collecting context is current on this thread) glGetError is read
  // too, and what it holds is named when KHR_debug reported nothing since it was last read;
  // otherwise only what KHR_debug reported.
  std::string take(bool contextCurrent);
  // Detaches from the context, which must be current.
  void stop();

 private:
  static void report(unsigned int source, unsigned int type, unsigned int id, unsigned int severity,
                     int length, const char* message, const void* collector);
  bool debugOutput_ = false;
  std::mutex mutex_;  // a context may be used from another thread than the one that made it
  std::vector<std::string> reported_;
  // KHR_debug reported an error since glGetError was last read.
  bool reportedUndrained_ = false;
};

}  // namespace ivshadow::test
