#pragma once

#include <atomic>

namespace ivshadow {

// While it lives, SIGINT, SIGTERM and SIGHUP set flag() instead of ending the process, so that
// a command can stop its work, remove what it had begun to write and say so (exit 128 + the
// signal: 130, 143, 129); the previous handlers come back with its end. One at a time.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static std::atomic<bool>& flag();
  static bool interrupted() { return flag().load(); }
  // 128 + the signal that came (the shell's status of a process it ended), 130 if none did.
  static int exitStatus();

 private:
  void (*previousInt_)(int);
  void (*previousTerm_)(int);
  void (*previousHup_)(int);
};

}  // namespace ivshadow
