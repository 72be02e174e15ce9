// carom tool: `carom run SCENE`, advancing a scene file's world by a time, a number of steps or a
// number of collisions, and writing frames, contact events, the end state and a summary.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the run verb and its options to app.
[[nodiscard]] Command add_run_command(CLI::App& app);

}  // namespace carom::cli
