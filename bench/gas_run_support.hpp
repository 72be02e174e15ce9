// carom benchmarks: what the hard-disk gas programs (carom_world_gas_probe, carom_textbook_gas)
// share so that their figures compare: the CPU clock they are timed by, and the random order in
// which SHUFFLED=1 numbers the disks (one permutation for both, by construction).
#pragma once

#include <algorithm>
#include <cstddef>
#include <ctime>
#include <random>
#include <vector>

namespace carom::bench {

// This process's CPU time in seconds: meaningful on a machine that other jobs share.
inline double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// 0 .. count − 1 in SHUFFLED=1's random order: position k of the shuffled numbering holds the
// disk that was number order[k].
inline std::vector<std::size_t> shuffled_order(std::size_t count) {
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(2));
  return order;
}

}  // namespace carom::bench
