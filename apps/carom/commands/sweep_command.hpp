// carom tool: `carom sweep`, the time of impact and bounce of two moving balls.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the sweep verb and its options to app.
[[nodiscard]] Command add_sweep_command(CLI::App& app);

}  // namespace carom::cli
