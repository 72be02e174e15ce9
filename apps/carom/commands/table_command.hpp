// carom tool: `carom table`, a standard pool table (7, 8 or 9 feet) with a rack, written as a
// scene file to run, shoot or edit.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the table verb and its options to app.
[[nodiscard]] Command add_table_command(CLI::App& app);

}  // namespace carom::cli
