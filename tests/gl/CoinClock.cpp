#include "tests/gl/CoinClock.h"

// Declared with default visibility (the build hides symbols unless told): the executable's
// definition must be exported for Coin's calls to reach it.
#pragma GCC visibility push(default)
#include <Inventor/SbTime.h>
#pragma GCC visibility pop
#include <Inventor/C/base/time.h>

#include <atomic>

namespace {

// Only ever moved forwards: Coin's clock never runs backwards.
std::atomic<double> offsetSeconds{0.0};

}  // namespace

SbTime SbTime::getTimeOfDay() {
  return SbTime(cc_time_gettimeofday() + offsetSeconds.load());
}

namespace ivshadow::test {

void advanceCoinClock(double seconds) {
  if (seconds <= 0.0) return;
  double now = offsetSeconds.load();
  while (!offsetSeconds.compare_exchange_weak(now, now + seconds)) {
  }
}

}  // namespace ivshadow::test
