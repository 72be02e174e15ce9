// carom tool: another program run to its end, its standard output kept. `carom bench --goals` runs
// each gas as `carom bench ... --json` in a process of its own: a process's peak resident set
// never falls, so gases run one after another in one process would hide each other's memory.
#pragma once

#include <string>
#include <vector>

namespace carom::cli {

// Runs `program` (a path, not searched for) with `args` (after the program's name), its standard
// input and error the caller's, and returns everything it wrote to standard output. Throws
// std::runtime_error when it cannot be started, exits with a status other than 0, or is killed
// (the signal named). POSIX only.
[[nodiscard]] std::string output_of_program(const std::string& program,
                                            const std::vector<std::string>& args);

}  // namespace carom::cli
