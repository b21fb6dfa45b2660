#pragma once

#include "ivshadow/Export.h"

#include <atomic>
#include <functional>

namespace ivshadow {

// The number of workers parallelRows uses for `requested` (0: one per core).
IVSHADOW_INTERNAL int workerCount(int requested);

// Calls work(row, worker) for rows [0, rows) on workerCount(threads) threads, the calling one
// included. Rows are handed out one at a time, since rows cost very differently (sky against
// stacked glass). Stops handing out rows once `cancel` is set.
IVSHADOW_INTERNAL void parallelRows(int rows, int threads,
                                    const std::function<void(int row, int worker)>& work,
                                    const std::atomic<bool>* cancel = nullptr);

}  // namespace ivshadow
