// carom tool: Ctrl-C (SIGINT) and SIGTERM (kill, timeout, batch schedulers) as a request to stop.
//
// While a StopOnSignals lives, the first of them sets a flag that the verb's loops and every world
// it runs watch (a world through its progress callback, so that a run stops within
// World::kStopCheckEvents events whether contacts happen or not); the verb then ends cleanly with
// its outputs complete up to that time and exits with 128 + the signal (130, 143). A second signal
// ends the process at once, removing the temporary files of outputs not yet complete.
#pragma once

#include <functional>
#include <string>

#include "carom/world.hpp"

namespace carom::cli {

class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  // Whether a stop was asked for since the StopOnSignals was made.
  [[nodiscard]] static bool requested() noexcept;
  // The exit status for a stopped verb: 128 + the signal (130 for SIGINT, 143 for SIGTERM).
  [[nodiscard]] static int exit_code() noexcept;
  // "interrupted (Ctrl-C)" or "terminated (SIGTERM)", for the closing message.
  [[nodiscard]] static std::string what() noexcept;
};

// Makes world's runs stop when a signal arrives; `progress`, when given, is called beside it
// (every World::kStopCheckEvents events) for a progress report.
void stop_world_on_signals(World& world, std::function<void(const RunStatus&)> progress = nullptr);

// Temporary files that a second signal removes before the process ends. Paths longer than
// 4095 bytes, or past 64 at once, are not tracked (they are left behind by a second signal).
class TemporaryFileGuard {
 public:
  TemporaryFileGuard() = default;
  explicit TemporaryFileGuard(const std::string& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(TemporaryFileGuard&& other) noexcept;
  TemporaryFileGuard& operator=(TemporaryFileGuard&& other) noexcept;
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace carom::cli
