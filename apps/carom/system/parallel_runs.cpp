#include "system/parallel_runs.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace carom::cli {

void run_in_parallel(std::size_t count, std::size_t threads, const std::function<bool()>& stop,
                     const std::function<void(std::size_t, std::atomic<double>&)>& run,
                     const std::function<void(double)>& watch) {
  std::vector<std::atomic<double>> progress(count);
  std::atomic<std::size_t> next{0};
  std::mutex ending;
  std::condition_variable ended;
  std::size_t workers_ended = 0;
  const auto worker = [&] {
    for (std::size_t j = next++; j < count && !stop(); j = next++) {
      run(j, progress[j]);
      progress[j].store(1.0);
    }
    const std::lock_guard<std::mutex> lock(ending);
    ++workers_ended;
    ended.notify_one();
  };
  const std::size_t workers = std::min(std::max<std::size_t>(threads, 1), count);
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(worker);
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(ending);
      if (ended.wait_for(lock, std::chrono::milliseconds(100),
                         [&] { return workers_ended == workers; })) {
        break;
      }
    }
    if (watch) {
      double sum = 0.0;
      for (const std::atomic<double>& fraction : progress) sum += fraction.load();
      watch(sum / static_cast<double>(count));
    }
  }
  for (std::thread& thread : pool) thread.join();
}

}  // namespace carom::cli
