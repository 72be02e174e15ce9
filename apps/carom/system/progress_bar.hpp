// carom tool: a progress bar with the rate and the time left, drawn on stderr only when stderr is
// a terminal (so logs and pipes stay clean).
#pragma once

#include <chrono>
#include <string>

namespace carom::cli {

class ProgressBar {
 public:
  // enabled: whether to draw at all (false for --quiet); drawing also needs a terminal.
  explicit ProgressBar(bool enabled);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // fraction in [0, 1] of the run done; rate_text e.g. "1.2e6 collisions/s". Redraws at most
  // ten times a second.
  void update(double fraction, const std::string& rate_text);
  // Clears the bar's line.
  void finish();

 private:
  bool active_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

// "12s", "3m05s", "1h02m".
[[nodiscard]] std::string duration_text(double seconds);

}  // namespace carom::cli
