// carom tool: `carom eos`, the equation of state Z(η) of hard disks: one `carom gas` run per
// packing fraction, the points spread over threads (one World per thread), and a table and plot
// beside Henderson's equation of state.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

[[nodiscard]] Command add_eos_command(CLI::App& app);

}  // namespace carom::cli
