// carom tool: `carom info SCENE`, what a scene file holds and whether it is valid.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the info verb and its options to app.
[[nodiscard]] Command add_info_command(CLI::App& app);

}  // namespace carom::cli
