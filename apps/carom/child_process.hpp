// carom tool: work done in a child process, for figures that a process keeps for its whole life
// (`carom bench --goals` measures each gas's memory as its own process's peak resident set, which
// never falls, so gases run one after another in one process would hide each other's).
#pragma once

#include <functional>
#include <string>

namespace carom::cli {

// Runs `work` in a child process (fork) and returns the text it returned. Throws
// std::runtime_error when the child cannot be started, or ends other than by returning (it threw:
// its message is then written to standard error by the child; it was killed: the signal named).
// POSIX only; the caller must have no other threads running.
[[nodiscard]] std::string output_of_child(const std::function<std::string()>& work);

}  // namespace carom::cli
