#pragma once

namespace ivshadow::test {

// Coin's clock in the GL tests: SbTime::getTimeOfDay, which Coin's sensors read (an
// SoAlarmSensor's trigger time, the timer queue that fires it), is replaced in the test
// executable by the wall clock plus an offset the tests move on. A test that waits for one of
// Coin's alarms advances the clock past it instead of sleeping, and the wait takes no time
// and cannot come out short on a loaded machine. (Coin calls it through its procedure linkage
// table, so the executable's definition is the one every caller gets: CoinClock.cpp.)
void advanceCoinClock(double seconds);

}  // namespace ivshadow::test
