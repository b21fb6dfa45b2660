#pragma once

#include <atomic>

namespace ivshadow {

// While it lives, SIGINT and SIGTERM set flag() instead of ending the process, so that a
// command can stop its work, clean up and say so (exit 130); the previous handlers come back
// with its end. One at a time.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static std::atomic<bool>& flag();
  static bool interrupted() { return flag().load(); }

 private:
  void (*previousInt_)(int);
  void (*previousTerm_)(int);
};

}  // namespace ivshadow
