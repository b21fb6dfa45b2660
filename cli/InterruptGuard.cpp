#include "cli/InterruptGuard.h"

#include <csignal>

namespace ivshadow {
namespace {

std::atomic<int>& received() {
  static std::atomic<int> signal{0};
  return signal;
}

extern "C" void onInterrupt(int signal) {
  received().store(signal);
  InterruptGuard::flag().store(true);
}

}  // namespace

std::atomic<bool>& InterruptGuard::flag() {
  static std::atomic<bool> interrupted{false};
  return interrupted;
}

int InterruptGuard::exitStatus() {
  const int signal = received().load();
  return 128 + (signal != 0 ? signal : SIGINT);
}

InterruptGuard::InterruptGuard() {
  flag().store(false);
  received().store(0);
  previousInt_ = std::signal(SIGINT, onInterrupt);
  previousTerm_ = std::signal(SIGTERM, onInterrupt);
  // A closed terminal or ssh session sends SIGHUP, which ended the process mid-write.
  previousHup_ = std::signal(SIGHUP, onInterrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, previousInt_);
  std::signal(SIGTERM, previousTerm_);
  std::signal(SIGHUP, previousHup_);
}

}  // namespace ivshadow
