#include "cli/InterruptGuard.h"

#include <csignal>

namespace ivshadow {
namespace {

extern "C" void onInterrupt(int) {
  InterruptGuard::flag().store(true);
}

}  // namespace

std::atomic<bool>& InterruptGuard::flag() {
  static std::atomic<bool> interrupted{false};
  return interrupted;
}

InterruptGuard::InterruptGuard() {
  flag().store(false);
  previousInt_ = std::signal(SIGINT, onInterrupt);
  previousTerm_ = std::signal(SIGTERM, onInterrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, previousInt_);
  std::signal(SIGTERM, previousTerm_);
}

}  // namespace ivshadow
