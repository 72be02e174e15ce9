// carom tool: `carom shot SCENE --ball NAME --speed V ...`, a cue strike on a pool scene run until
// every ball rests, with its events, a picture of the paths and the end state.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the shot verb and its options to app.
[[nodiscard]] Command add_shot_command(CLI::App& app);

}  // namespace carom::cli
