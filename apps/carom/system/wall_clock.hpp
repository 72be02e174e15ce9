// carom tool: wall-clock time, as the tool's reports give it (seconds on the steady clock, which
// no change of the system's clock moves).
#pragma once

#include <chrono>

namespace carom::cli {

// Seconds from `start` to now.
[[nodiscard]] inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace carom::cli
