// carom tool: `carom bench`, the collision rate of the event-driven world on a gas of equal
// hard disks in a periodic box (the gas of carom/science/hard_disk_gas.hpp).
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the bench verb and its options to app.
[[nodiscard]] Command add_bench_command(CLI::App& app);

}  // namespace carom::cli
