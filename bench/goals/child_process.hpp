// carom_bench_goals: another program run to its end, its standard output kept, and Ctrl-C or
// SIGTERM passed on to it. Each gas runs as `carom bench ... --json` in a process of its own: a
// process's peak resident set never falls, so gases run one after another in one process would
// hide each other's memory.
#pragma once

#include <string>
#include <vector>

namespace carom::goals {

// While one lives, SIGINT (Ctrl-C) and SIGTERM ask this program to stop: the first is recorded
// and passed on to the program that output_of_program is running, if any, so that it stops too
// even when only this process was sent the signal (kill, timeout); a second ends this process at
// once with status 128 + the signal.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The first signal received since the StopSignals was made (0: none).
  [[nodiscard]] static int received() noexcept;
  // "interrupted (Ctrl-C)" or "terminated (SIGTERM)", for the closing message.
  [[nodiscard]] static std::string what() noexcept;
};

// Runs `program` (a path, not searched for) with `args` (after the program's name), its standard
// input and error the caller's, and returns everything it wrote to standard output. Throws
// std::runtime_error when it cannot be started, exits with a status other than 0, or is killed
// (the signal named). POSIX only.
[[nodiscard]] std::string output_of_program(const std::string& program,
                                            const std::vector<std::string>& args);

}  // namespace carom::goals
