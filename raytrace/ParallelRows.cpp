#include "raytrace/ParallelRows.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace ivshadow {

int workerCount(int requested) {
  return requested > 0 ? requested : std::max(1, int(std::thread::hardware_concurrency()));
}

void parallelRows(int rows, int threads, const std::function<void(int, int)>& work,
                  const std::atomic<bool>* cancel) {
  std::atomic<int> next{0};
  const auto run = [&](int worker) {
    for (int row = next++; row < rows; row = next++) {
      if (cancel != nullptr && cancel->load()) return;
      work(row, worker);
    }
  };
  std::vector<std::thread> workers;
  const int count = workerCount(threads);
  for (int i = 1; i < count; ++i) workers.emplace_back(run, i);
  run(0);
  for (std::thread& worker : workers) worker.join();
}

}  // namespace ivshadow
